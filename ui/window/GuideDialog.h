#pragma once
// Help ▸ Editor Guide: docs/EDITOR.md, built into the editor (resources/resources.qrc) so that the
// guide is there wherever the editor is installed, shown as formatted text with its pictures.
#include <QDialog>

class QTextBrowser;

namespace airtrap {

class GuideDialog : public QDialog {
    Q_OBJECT

public:
    explicit GuideDialog(QWidget* parent = nullptr);

    //! The guide's text as shown, for tests.
    const QTextBrowser* browser() const { return browser_; }

    //! Where the guide is in the editor's resources.
    static constexpr const char* kGuideResource = ":/docs/EDITOR.md";

private:
    //! Scales down every picture wider than `width` pixels to that width.
    void fitImages(int width);

    static constexpr int kImageWidth = 820;
    QTextBrowser* browser_;
};

} // namespace airtrap
