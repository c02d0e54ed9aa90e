#include "window/ExportDialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

namespace airtrap {

namespace {

QCheckBox* formatBox(const QString& text, const QString& tip, bool checked) {
    auto* box = new QCheckBox(text);
    box->setToolTip(tip);
    box->setChecked(checked);
    return box;
}

} // namespace

ExportDialog::ExportDialog(int lastFrame, const QString& folder, QWidget* parent)
    : QDialog(parent),
      obj_(formatBox(tr("OBJ meshes"),
                     tr("water_0001.obj (free surface), bubbles_0001.obj, bodies_0001.obj"), true)),
      vdb_(formatBox(tr("VDB volumes"), tr("fluid_0001.vdb with surface, density and vel"), false)),
      ply_(formatBox(tr("PLY points"), tr("particles_0001.ply and bubbles_0001.ply (pscale)"),
                     false)),
      first_(new QSpinBox), last_(new QSpinBox), folder_(new QLineEdit(folder)), up_(new QComboBox),
      buttons_(new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel)) {
    setWindowTitle(tr("Export"));
    for (QSpinBox* box : {first_, last_})
        box->setRange(1, std::max(1, lastFrame));
    first_->setValue(1);
    last_->setValue(std::max(1, lastFrame));
    up_->addItem(tr("Y up (Houdini, Maya)"), int(UpAxis::Y));
    up_->addItem(tr("Z up (Blender scene axes)"), int(UpAxis::Z));
    auto* browse = new QPushButton(tr("Browse…"));
    auto* folderRow = new QHBoxLayout;
    folderRow->addWidget(folder_);
    folderRow->addWidget(browse);
    auto* formats = new QVBoxLayout;
    for (QCheckBox* box : {obj_, vdb_, ply_})
        formats->addWidget(box);
    auto* frames = new QHBoxLayout;
    frames->addWidget(first_);
    frames->addWidget(last_);
    auto* form = new QFormLayout;
    form->addRow(tr("Formats"), formats);
    form->addRow(tr("Frames"), frames);
    form->addRow(tr("Folder"), folderRow);
    form->addRow(tr("Up axis"), up_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(buttons_);
    buttons_->button(QDialogButtonBox::Ok)->setText(tr("Export"));
    connect(buttons_, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons_, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &ExportDialog::chooseFolder);
    for (QCheckBox* box : {obj_, vdb_, ply_})
        connect(box, &QCheckBox::toggled, this, &ExportDialog::updateOk);
    for (QSpinBox* box : {first_, last_})
        connect(box, &QSpinBox::valueChanged, this, &ExportDialog::updateOk);
    connect(folder_, &QLineEdit::textChanged, this, &ExportDialog::updateOk);
    updateOk();
}

bool ExportDialog::acceptable() const {
    const bool anyFormat = obj_->isChecked() || vdb_->isChecked() || ply_->isChecked();
    return anyFormat && !folder_->text().trimmed().isEmpty() && first_->value() <= last_->value();
}

void ExportDialog::updateOk() {
    buttons_->button(QDialogButtonBox::Ok)->setEnabled(acceptable());
}

void ExportDialog::chooseFolder() {
    const QString chosen =
        QFileDialog::getExistingDirectory(this, tr("Export into"), folder_->text());
    if (!chosen.isEmpty())
        folder_->setText(chosen);
}

RenderRequest ExportDialog::request() const {
    RenderRequest request;
    if (obj_->isChecked())
        request.formats.push_back(ExportFormat::Obj);
    if (vdb_->isChecked())
        request.formats.push_back(ExportFormat::Vdb);
    if (ply_->isChecked())
        request.formats.push_back(ExportFormat::Ply);
    request.outDir = folder_->text().trimmed().toStdString();
    request.up = UpAxis(up_->currentData().toInt());
    request.firstFrame = first_->value();
    request.lastFrame = last_->value();
    return request;
}

} // namespace airtrap
