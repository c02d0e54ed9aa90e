#pragma once
// Asked before the first bake of a scene whose own folder cannot be written (an installed samples
// folder): where its frames go. The default is a folder of the scene's own in the user's cache
// location; "Choose Folder…" puts "<name>.cache" in a folder the user picks.
#include <QString>

class QWidget;

namespace airtrap {

class CacheFolderQuestion {
public:
    //! The cache folder for the scene at `scenePath`, `proposed` by default; empty when the user
    //! cancelled.
    static QString ask(QWidget* parent, const QString& scenePath, const QString& proposed);
};

} // namespace airtrap
