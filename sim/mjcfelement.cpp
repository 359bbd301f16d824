// SPDX-License-Identifier: MIT
#include "mjcfelement.h"

#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <algorithm>

namespace semhap {

namespace {

// An MJCF nests a few levels per body: far deeper is a hostile file, not a robot.
constexpr int MaxDepth = 256;

void write(QXmlStreamWriter &writer, const MjcfElement &element)
{
    writer.writeStartElement(element.tag());
    for (const auto &[name, value] : element.attributes())
        writer.writeAttribute(name, value);
    for (const MjcfElement &child : element.children())
        write(writer, child);
    writer.writeEndElement();
}

} // namespace

bool MjcfElement::parse(const QByteArray &xml, MjcfElement *root, QString *error)
{
    QXmlStreamReader reader(xml);
    std::vector<MjcfElement *> open;
    *root = MjcfElement();
    bool haveRoot = false;
    while (!reader.atEnd()) {
        reader.readNext();
        if (reader.isStartElement()) {
            MjcfElement *element = nullptr;
            if (open.empty()) {
                if (haveRoot)
                    break;
                haveRoot = true;
                element = root;
            } else {
                if (int(open.size()) >= MaxDepth) {
                    *error = QStringLiteral("%1:%2: elements nested deeper than %3")
                                 .arg(reader.lineNumber())
                                 .arg(reader.columnNumber())
                                 .arg(MaxDepth);
                    return false;
                }
                open.back()->m_children.emplace_back();
                element = &open.back()->m_children.back();
            }
            element->m_tag = reader.name().toString();
            element->m_line = int(reader.lineNumber());
            for (const QXmlStreamAttribute &a : reader.attributes())
                element->m_attributes.emplace_back(a.qualifiedName().toString(),
                                                   a.value().toString());
            open.push_back(element);
        } else if (reader.isEndElement()) {
            open.pop_back();
        }
    }
    if (reader.hasError() || !haveRoot) {
        *error = QStringLiteral("%1:%2: %3")
                     .arg(reader.lineNumber())
                     .arg(reader.columnNumber())
                     .arg(haveRoot ? reader.errorString() : QStringLiteral("no root element"));
        return false;
    }
    return true;
}

QByteArray MjcfElement::toXml() const
{
    QByteArray out;
    QXmlStreamWriter writer(&out);
    writer.setAutoFormatting(true);
    writer.writeStartDocument();
    write(writer, *this);
    writer.writeEndDocument();
    return out;
}

bool MjcfElement::has(const QString &name) const
{
    return std::any_of(m_attributes.begin(), m_attributes.end(),
                       [&](const auto &a) { return a.first == name; });
}

QString MjcfElement::attribute(const QString &name) const
{
    for (const auto &[key, value] : m_attributes) {
        if (key == name)
            return value;
    }
    return QString();
}

void MjcfElement::setAttribute(const QString &name, const QString &value)
{
    for (auto &[key, old] : m_attributes) {
        if (key == name) {
            old = value;
            return;
        }
    }
    m_attributes.emplace_back(name, value);
}

void MjcfElement::removeAttribute(const QString &name)
{
    m_attributes.erase(std::remove_if(m_attributes.begin(), m_attributes.end(),
                                      [&](const auto &a) { return a.first == name; }),
                       m_attributes.end());
}

MjcfElement *MjcfElement::child(const QString &tag)
{
    for (MjcfElement &c : m_children) {
        if (c.m_tag == tag)
            return &c;
    }
    return nullptr;
}

const MjcfElement *MjcfElement::child(const QString &tag) const
{
    return const_cast<MjcfElement *>(this)->child(tag);
}

MjcfElement &MjcfElement::section(const QString &tag)
{
    if (MjcfElement *found = child(tag))
        return *found;
    m_children.emplace_back(tag);
    return m_children.back();
}

MjcfElement *MjcfElement::find(const QString &tag, const QString &name)
{
    if (m_tag == tag && attribute(QStringLiteral("name")) == name)
        return this;
    for (MjcfElement &c : m_children) {
        if (MjcfElement *found = c.find(tag, name))
            return found;
    }
    return nullptr;
}

void MjcfElement::forEach(const std::function<void(MjcfElement &)> &visit)
{
    visit(*this);
    for (MjcfElement &c : m_children)
        c.forEach(visit);
}

void MjcfElement::forEach(const std::function<void(const MjcfElement &)> &visit) const
{
    visit(*this);
    for (const MjcfElement &c : m_children)
        c.forEach(visit);
}

void MjcfElement::removeChildren(const std::function<bool(const MjcfElement &)> &drop)
{
    m_children.erase(std::remove_if(m_children.begin(), m_children.end(), drop), m_children.end());
}

} // namespace semhap
