// SPDX-License-Identifier: MIT
#pragma once

#include <QByteArray>
#include <QString>

#include <functional>
#include <utility>
#include <vector>

namespace semhap {

/**
 * An element of an MJCF document held as a tree, for the edits MuJoCo 2.2 cannot make on a
 * compiled model: putting one model into another (a gripper into a scene's wrist). Comments
 * and text between elements are dropped; attributes keep their order.
 */
class MjcfElement
{
public:
    MjcfElement() = default;
    explicit MjcfElement(const QString &tag) : m_tag(tag) {}

    /** Parses a whole document; false with `LINE:COL: reason` in `error`. */
    static bool parse(const QByteArray &xml, MjcfElement *root, QString *error);
    /** The document again, indented. */
    QByteArray toXml() const;

    const QString &tag() const { return m_tag; }
    /** Where the element began in the parsed document (1-based; 0 for a new element). */
    int line() const { return m_line; }

    bool has(const QString &name) const;
    /** The attribute's value; empty when it has none. */
    QString attribute(const QString &name) const;
    void setAttribute(const QString &name, const QString &value);
    void removeAttribute(const QString &name);
    const std::vector<std::pair<QString, QString>> &attributes() const { return m_attributes; }

    std::vector<MjcfElement> &children() { return m_children; }
    const std::vector<MjcfElement> &children() const { return m_children; }
    /** The first child with `tag`, or null. */
    MjcfElement *child(const QString &tag);
    const MjcfElement *child(const QString &tag) const;
    /** The first child with `tag`, appended when there is none. */
    MjcfElement &section(const QString &tag);
    /** The first element below this one (depth first) with `tag` and attribute name=`name`. */
    MjcfElement *find(const QString &tag, const QString &name);
    /** Calls `visit` on this element and every element below it, depth first. */
    void forEach(const std::function<void(MjcfElement &)> &visit);
    void forEach(const std::function<void(const MjcfElement &)> &visit) const;
    /** Removes the children for which `drop` is true (not their descendants' children). */
    void removeChildren(const std::function<bool(const MjcfElement &)> &drop);

private:
    QString m_tag;
    int m_line = 0;
    std::vector<std::pair<QString, QString>> m_attributes;
    std::vector<MjcfElement> m_children;
};

} // namespace semhap
