#include "window/GuideDialog.h"

#include <QDialogButtonBox>
#include <QFile>
#include <QImage>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QTextDocument>
#include <QVBoxLayout>

namespace airtrap {

GuideDialog::GuideDialog(QWidget* parent) : QDialog(parent), browser_(new QTextBrowser(this)) {
    setObjectName(QStringLiteral("guideDialog"));
    setWindowTitle(tr("Airtrap Editor Guide"));
    browser_->setObjectName(QStringLiteral("guideBrowser"));
    browser_->setOpenExternalLinks(true);
    // The guide's pictures are named relative to it ("images/editor.png").
    browser_->setSearchPaths({QStringLiteral(":/docs")});
    QFile guide(QString::fromLatin1(kGuideResource));
    if (guide.open(QIODevice::ReadOnly | QIODevice::Text)) {
        browser_->setMarkdown(QString::fromUtf8(guide.readAll()));
        fitImages(kImageWidth);
    } else
        browser_->setPlainText(tr("The guide is missing from this build (%1).")
                                   .arg(QString::fromLatin1(kGuideResource)));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(browser_);
    layout->addWidget(buttons);
    resize(900, 760);
}

void GuideDialog::fitImages(int width) {
    // Markdown images come at their own size (the editor's picture is 1600 pixels wide); set
    // alone, the width scales the height with it.
    QTextDocument* document = browser_->document();
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next())
        for (auto fragment = block.begin(); !fragment.atEnd(); ++fragment) {
            const QTextFragment part = fragment.fragment();
            if (!part.isValid() || !part.charFormat().isImageFormat())
                continue;
            QTextImageFormat image = part.charFormat().toImageFormat();
            const QImage picture(image.name().startsWith(QLatin1Char(':'))
                                     ? image.name()
                                     : QStringLiteral(":/docs/") + image.name());
            if (picture.width() <= width)
                continue;
            image.setWidth(width);
            QTextCursor cursor(document);
            cursor.setPosition(part.position());
            cursor.setPosition(part.position() + part.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(image);
        }
}

} // namespace airtrap
