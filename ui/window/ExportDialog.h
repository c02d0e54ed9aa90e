#pragma once
// Asks what to export (docs/CLI.md "export"): which sequences (OBJ meshes, VDB volumes, PLY
// points), which frames, into which folder, with which axis up. The export itself runs in the
// background (RenderOutputController); this dialog only gathers the request.
#include "controller/RenderJob.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLineEdit;
class QSpinBox;

namespace airtrap {

class ExportDialog : public QDialog {
    Q_OBJECT

public:
    //! `lastFrame` is the newest cached frame; `folder` the suggested output folder.
    ExportDialog(int lastFrame, const QString& folder, QWidget* parent = nullptr);

    //! The choices as a request (the caller adds the cache and the render settings).
    RenderRequest request() const;

    // For tests and keyboard users: the widgets by role.
    QCheckBox* objBox() const { return obj_; }
    QCheckBox* vdbBox() const { return vdb_; }
    QCheckBox* plyBox() const { return ply_; }
    QSpinBox* firstFrameBox() const { return first_; }
    QSpinBox* lastFrameBox() const { return last_; }
    QLineEdit* folderField() const { return folder_; }
    QComboBox* upAxisBox() const { return up_; }
    //! True when the choices make an export (a format, a folder, first ≤ last).
    bool acceptable() const;

private:
    void chooseFolder();
    void updateOk();

    QCheckBox* obj_;
    QCheckBox* vdb_;
    QCheckBox* ply_;
    QSpinBox* first_;
    QSpinBox* last_;
    QLineEdit* folder_;
    QComboBox* up_;
    QDialogButtonBox* buttons_;
};

} // namespace airtrap
