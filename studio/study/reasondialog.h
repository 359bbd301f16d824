// SPDX-License-Identifier: MIT
#pragma once

#include <QDialog>

class QLineEdit;
class QPushButton;

namespace semhap {

/**
 * Asks the experimenter why an attempt does not count (aborted, marked invalid): OK is
 * offered only once a reason is typed, since the study keeps one with every such attempt.
 */
class ReasonDialog : public QDialog
{
    Q_OBJECT

public:
    ReasonDialog(const QString &title, const QString &question, QWidget *parent = nullptr);

    /** The reason typed, trimmed. */
    QString reason() const;
    QLineEdit *edit() const { return m_edit; }
    QPushButton *okButton() const { return m_ok; }

    /** Asks (modal); the reason, or empty when cancelled. */
    static QString ask(QWidget *parent, const QString &title, const QString &question);

private:
    QLineEdit *m_edit = nullptr;
    QPushButton *m_ok = nullptr;
};

} // namespace semhap
