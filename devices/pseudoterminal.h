// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

namespace semhap {

/**
 * The pseudo-terminal a band in software serves on (`semhap emulate --pty`, `semhap
 * bandsim`): raw from the start, its other side held open so that it survives hosts coming
 * and going, and optionally a symlink kept pointing at it (removed again on destruction).
 */
class PseudoTerminal
{
public:
    PseudoTerminal() = default;
    ~PseudoTerminal();
    PseudoTerminal(const PseudoTerminal &) = delete;
    PseudoTerminal &operator=(const PseudoTerminal &) = delete;

    /**
     * Creates the pty and, when `link` is not empty, a symlink to it there (a stale link is
     * replaced, anything else refused); false with `error`.
     */
    bool open(const QString &link, QString *error);
    /** The band's side (the master), non-blocking; -1 before open(). */
    int fd() const { return m_fd; }
    /** The host's side, `/dev/pts/N`. */
    const QString &path() const { return m_path; }

private:
    bool makeLink(QString *error);

    int m_fd = -1;
    int m_slaveFd = -1; ///< held open so the pty survives hosts coming and going
    QString m_path;
    QString m_link;
};

} // namespace semhap
