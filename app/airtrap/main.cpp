// airtrap: the editor.
#include "window/MainWindow.h"
#include "viewport/ViewportWidget.h"

#include <QApplication>
#include <QIcon>
#include <QSurfaceFormat>

int main(int argc, char* argv[]) {
    // Before QApplication: the default format decides how Qt sets up its shared OpenGL contexts,
    // and a core-profile viewport needs them to be core profile too.
    QSurfaceFormat::setDefaultFormat(airtrap::ViewportWidget::surfaceFormat());

    QApplication app(argc, argv);
    app.setWindowIcon(QIcon(":/icons/airtrap.png"));
    QApplication::setOrganizationName(QStringLiteral("Airtrap"));
    QApplication::setApplicationName(QStringLiteral("Airtrap"));
    QApplication::setApplicationVersion(QStringLiteral(AIRTRAP_VERSION));

    airtrap::MainWindow window;
    window.show();
    return app.exec();
}
