#include "window/MainWindow.h"

#include "viewport/ViewportWidget.h"

#include <QAction>
#include <QCloseEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QKeySequence>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <fstream>
#include <nlohmann/json.hpp>

namespace airtrap {

namespace {

// Named explicitly rather than taken from QApplication so that tests, which do not set the
// application's names, read and write the same store as the editor.
constexpr auto kSettingsOrganisation = "Airtrap";
constexpr auto kSettingsApplication = "Airtrap";
constexpr auto kGeometryKey = "mainWindow/geometry";

} // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(QStringLiteral("Airtrap"));
    viewport_ = new ViewportWidget(this);
    viewport_->setObjectName(QStringLiteral("viewport"));
    setCentralWidget(viewport_);
    createMenus();
    statusBar()->showMessage(tr("Ready"));
    restoreSettings();
}

void MainWindow::createMenus() {
    fileMenu_ = menuBar()->addMenu(tr("&File"));
    fileMenu_->setObjectName(QStringLiteral("fileMenu"));

    openSceneAction_ = fileMenu_->addAction(tr("&Open Scene…"));
    openSceneAction_->setObjectName(QStringLiteral("openSceneAction"));
    openSceneAction_->setShortcut(QKeySequence::Open);
    connect(openSceneAction_, &QAction::triggered, this, &MainWindow::chooseScene);

    fileMenu_->addSeparator();

    quitAction_ = fileMenu_->addAction(tr("&Quit"));
    quitAction_->setObjectName(QStringLiteral("quitAction"));
    // Spelled out: QKeySequence::Quit is empty on some desktops, Ctrl+Q is what users expect.
    quitAction_->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_Q));
    quitAction_->setMenuRole(QAction::QuitRole);
    connect(quitAction_, &QAction::triggered, this, &MainWindow::close);

    QMenu* helpMenu = menuBar()->addMenu(tr("&Help"));
    helpMenu->setObjectName(QStringLiteral("helpMenu"));
    QAction* aboutAction = helpMenu->addAction(tr("&About Airtrap"));
    aboutAction->setMenuRole(QAction::AboutRole);
    connect(aboutAction, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::chooseScene() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open Scene"), QString(),
                                                      tr("Airtrap scenes (*.json);;All files (*)"));
    if (!path.isEmpty()) {
        openScene(path);
    }
}

bool MainWindow::openScene(const QString& path) {
    // Plain JSON on purpose: the editor does not edit scenes yet, so naming the file is all it
    // claims to do. Validation belongs to the engine's scene reader once the editor uses it.
    std::ifstream in(QFileInfo(path).absoluteFilePath().toStdString(), std::ios::binary);
    if (!in) {
        statusBar()->showMessage(tr("Cannot open %1").arg(path));
        return false;
    }
    const nlohmann::json json = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    if (json.is_discarded() || !json.is_object()) {
        statusBar()->showMessage(tr("%1 is not a JSON scene").arg(path));
        return false;
    }
    QString name = tr("(unnamed)");
    if (const auto it = json.find("name"); it != json.end() && it->is_string()) {
        name = QString::fromStdString(it->get<std::string>());
    }
    statusBar()->showMessage(
        tr("Scene “%1” — %2 (viewing and editing come later)").arg(name, path));
    return true;
}

void MainWindow::showAbout() {
    QMessageBox::about(this, tr("About Airtrap"),
                       tr("<h3>Airtrap %1</h3>"
                          "<p>SPH water with trapped air bubbles, after Oh &amp; Jeong, "
                          "“Single-Phase Trapped Air Simulation in Water Flow” (WSCG 2014).</p>")
                           .arg(QStringLiteral(AIRTRAP_VERSION)));
}

void MainWindow::closeEvent(QCloseEvent* event) {
    saveSettings();
    QMainWindow::closeEvent(event);
}

void MainWindow::restoreSettings() {
    const QSettings settings(kSettingsOrganisation, kSettingsApplication);
    const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
    if (geometry.isEmpty() || !restoreGeometry(geometry)) {
        resize(1280, 800);
    }
}

void MainWindow::saveSettings() const {
    QSettings settings(kSettingsOrganisation, kSettingsApplication);
    settings.setValue(kGeometryKey, saveGeometry());
}

} // namespace airtrap
