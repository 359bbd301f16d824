// SPDX-License-Identifier: MIT
#include "manualwindow.h"

#include "windowplacement.h"

#include <QDesktopServices>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QShortcut>
#include <QStyle>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QToolButton>
#include <QVBoxLayout>

namespace semhap {

namespace {

/**
 * The manual's pages as Markdown, their screenshots scaled to the page's width (they are
 * taken at 1280 px and more, wider than the window).
 */
class PageBrowser : public QTextBrowser
{
public:
    using QTextBrowser::QTextBrowser;

protected:
    QVariant loadResource(int type, const QUrl &name) override
    {
        QVariant resource = QTextBrowser::loadResource(type, name);
        if (type != QTextDocument::ImageResource)
            return resource;
        QImage image = resource.value<QImage>();
        if (image.isNull())
            image.loadFromData(resource.toByteArray());
        const int room = viewport()->width() - 40;
        if (!image.isNull() && room > 0 && image.width() > room)
            return image.scaledToWidth(room, Qt::SmoothTransformation);
        return image.isNull() ? resource : QVariant(image);
    }
};

/** GitHub's anchor of a heading, which the pages' links use: `#running-a-study`. */
QString slug(const QString &heading)
{
    QString out;
    for (const QChar c : heading.toLower()) {
        if (c.isLetterOrNumber() || c == QLatin1Char('-') || c == QLatin1Char('_'))
            out += c;
        else if (c == QLatin1Char(' '))
            out += QLatin1Char('-');
    }
    return out;
}

/** Names each heading of `document` by its slug, so links to it (and scrollToAnchor) work. */
void nameHeadings(QTextDocument *document)
{
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        if (block.blockFormat().headingLevel() == 0 || block.text().isEmpty())
            continue;
        QTextCursor cursor(block);
        cursor.movePosition(QTextCursor::EndOfBlock, QTextCursor::KeepAnchor);
        QTextCharFormat format;
        format.setAnchor(true);
        format.setAnchorNames({slug(block.text())});
        cursor.mergeCharFormat(format);
    }
}

QToolButton *navigationButton(QWidget *parent, const QString &name, QStyle::StandardPixmap icon,
                              const QString &tip)
{
    auto *button = new QToolButton(parent);
    button->setObjectName(name);
    button->setIcon(parent->style()->standardIcon(icon));
    button->setToolTip(tip);
    button->setAutoRaise(true);
    return button;
}

} // namespace

ManualWindow::ManualWindow(QWidget *window, const QUrl &url) : QDialog(window)
{
    setObjectName(QStringLiteral("manualWindow"));
    setWindowTitle(tr("semhap studio manual"));
    m_browser = new PageBrowser(this);
    m_browser->setObjectName(QStringLiteral("manualBrowser"));
    // Pages of the manual open here; the web opens in the desktop's browser.
    m_browser->setOpenLinks(false);
    connect(m_browser, &QTextBrowser::anchorClicked, this, [this](const QUrl &link) {
        const QUrl target = m_browser->source().resolved(link);
        if (target.isLocalFile() || target.scheme() == QLatin1String("qrc"))
            m_browser->setSource(target);
        else
            QDesktopServices::openUrl(target);
    });

    auto *back = navigationButton(this, QStringLiteral("manualBack"), QStyle::SP_ArrowBack,
                                  tr("Back (Alt+Left)"));
    auto *forward = navigationButton(this, QStringLiteral("manualForward"),
                                     QStyle::SP_ArrowForward, tr("Forward (Alt+Right)"));
    auto *home = navigationButton(this, QStringLiteral("manualHome"), QStyle::SP_DirHomeIcon,
                                  tr("The studio's manual"));
    back->setEnabled(false);
    forward->setEnabled(false);
    connect(back, &QToolButton::clicked, m_browser, &QTextBrowser::backward);
    connect(forward, &QToolButton::clicked, m_browser, &QTextBrowser::forward);
    connect(home, &QToolButton::clicked, this, [this, url] { m_browser->setSource(url); });
    connect(m_browser, &QTextBrowser::backwardAvailable, back, &QToolButton::setEnabled);
    connect(m_browser, &QTextBrowser::forwardAvailable, forward, &QToolButton::setEnabled);
    new QShortcut(QKeySequence::Back, this, m_browser, &QTextBrowser::backward);
    new QShortcut(QKeySequence::Forward, this, m_browser, &QTextBrowser::forward);

    m_search = new QLineEdit(this);
    m_search->setObjectName(QStringLiteral("manualSearch"));
    m_search->setPlaceholderText(tr("Search the page (Ctrl+F)"));
    m_search->setClearButtonEnabled(true);
    m_found = new QLabel(this);
    m_found->setObjectName(QStringLiteral("manualFound"));
    // Room for its words from the start: the search field does not jump when they show.
    m_found->setMinimumWidth(m_found->fontMetrics().horizontalAdvance(tr("Not found")) + 8);
    // As you type, from the top of the page; Enter: the next match.
    connect(m_search, &QLineEdit::textEdited, this, [this](const QString &text) {
        m_browser->moveCursor(QTextCursor::Start);
        find(text);
    });
    connect(m_search, &QLineEdit::returnPressed, this, [this] { find(m_search->text()); });
    new QShortcut(QKeySequence::Find, this, this, [this] {
        m_search->setFocus();
        m_search->selectAll();
    });
    connect(m_browser, &QTextBrowser::sourceChanged, this, [this](const QUrl &source) {
        nameHeadings(m_browser->document());
        if (source.hasFragment())
            m_browser->scrollToAnchor(source.fragment());
        m_found->clear();
        setWindowTitle(tr("semhap studio manual — %1").arg(m_browser->source().fileName()));
    });

    auto *bar = new QHBoxLayout;
    bar->addWidget(back);
    bar->addWidget(forward);
    bar->addWidget(home);
    bar->addSpacing(12);
    bar->addWidget(m_search, 1);
    bar->addWidget(m_found);
    auto *layout = new QVBoxLayout(this);
    layout->addLayout(bar);
    layout->addWidget(m_browser, 1);

    setGeometry(WindowPlacement::centredOver(window, QSize(900, 760)));
    new WindowPlacement(this);
    m_browser->setSource(url, QTextDocument::MarkdownResource);
}

bool ManualWindow::find(const QString &text)
{
    if (text.isEmpty()) {
        m_found->clear();
        return false;
    }
    bool found = m_browser->find(text);
    if (!found) {
        // Round to the top, as a browser's search goes on.
        m_browser->moveCursor(QTextCursor::Start);
        found = m_browser->find(text);
    }
    m_found->setText(found ? QString() : tr("Not found"));
    return found;
}

} // namespace semhap
