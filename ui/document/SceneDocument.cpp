#include "document/SceneDocument.h"

#include "commands/InsertElementCommand.h"
#include "commands/RemoveElementCommand.h"
#include "commands/SetParameterCommand.h"
#include "core/Error.h"
#include "document/EditDescription.h"
#include "scene/ParameterCodec.h"
#include "scene/SceneJson.h"
#include "scene/SceneSchema.h"

#include <QFileInfo>
#include <QUndoStack>
#include <cmath>

namespace airtrap {

namespace {

constexpr auto kNameKey = "name";

//! Spin boxes deliver doubles for integer parameters; the declaration decides what is stored.
ParameterValue normalised(const ParameterDeclaration& declaration, const ParameterValue& value) {
    if (declaration.kind == ParameterKind::Int)
        if (const auto* number = std::get_if<double>(&value))
            return static_cast<long long>(std::llround(*number));
    if (declaration.kind == ParameterKind::Real)
        if (const auto* integer = std::get_if<long long>(&value))
            return static_cast<double>(*integer);
    return value;
}

Scene defaultNewScene() {
    Scene scene;
    scene.name = "Untitled";
    FluidBlock water;
    water.name = "Water";
    water.min = Vec3d(0.0, 0.0, 0.0);
    water.max = Vec3d(0.4, 0.5, 1.0);
    scene.fluidBlocks.push_back(water);
    return scene;
}

} // namespace

SceneDocument::SceneDocument(QObject* parent)
    : QObject(parent), scene_(defaultNewScene()), undoStack_(new QUndoStack(this)) {
    connect(undoStack_, &QUndoStack::cleanChanged, this,
            [this](bool clean) { Q_EMIT modifiedChanged(!clean); });
}

QString SceneDocument::displayName() const {
    return filePath_.isEmpty() ? tr("Untitled") : QFileInfo(filePath_).fileName();
}

bool SceneDocument::isModified() const {
    return !undoStack_->isClean();
}

void SceneDocument::newScene() {
    replaceScene(defaultNewScene(), QString());
}

void SceneDocument::open(const QString& path) {
    // readSceneFile throws before anything here changes, so a bad file leaves the document as it
    // was.
    replaceScene(readSceneFile(path.toStdString()), QFileInfo(path).absoluteFilePath());
}

void SceneDocument::adoptScene(Scene scene) {
    replaceScene(std::move(scene), QString());
}

void SceneDocument::save(const QString& path) {
    const QString absolute = QFileInfo(path).absoluteFilePath();
    writeSceneFile(scene_, absolute.toStdString());
    scene_.sourcePath = absolute.toStdString();
    undoStack_->setClean();
    if (absolute != filePath_) {
        filePath_ = absolute;
        Q_EMIT filePathChanged(filePath_);
    }
}

void SceneDocument::replaceScene(Scene scene, const QString& path) {
    Q_EMIT aboutToReset();
    scene_ = std::move(scene);
    scene_.sourcePath = path.toStdString();
    undoStack_->clear();
    undoStack_->setClean();
    Q_EMIT reset();
    filePath_ = path;
    Q_EMIT filePathChanged(filePath_);
    Q_EMIT modifiedChanged(false);
}

// --- Edits --------------------------------------------------------------------------------------

QString SceneDocument::editParameter(const SceneItem& item, const std::string& key,
                                     const ParameterValue& value, int dragSession) {
    ParameterChange change;
    if (const QString refusal = checkedChange(item, key, value, change); !refusal.isEmpty())
        return refusal;
    if (change.oldValue == change.newValue)
        return {};
    const QString text =
        key == kNameKey
            ? tr("Rename %1 to %2")
                  .arg(elementName(item),
                       QString::fromStdString(std::get<std::string>(change.newValue)))
            : EditDescription::ofParameter(elementName(item), boundParameter(item, key).declaration,
                                           change.newValue);
    undoStack_->push(new SetParameterCommand(*this, item, {change}, dragSession, text));
    return {};
}

QString
SceneDocument::editParameters(const SceneItem& item,
                              const std::vector<std::pair<std::string, ParameterValue>>& values,
                              int dragSession, const QString& text) {
    std::vector<ParameterChange> changes(values.size());
    for (std::size_t i = 0; i < values.size(); ++i)
        if (const QString refusal =
                checkedChange(item, values[i].first, values[i].second, changes[i]);
            !refusal.isEmpty())
            return refusal;
    undoStack_->push(new SetParameterCommand(*this, item, std::move(changes), dragSession, text));
    return {};
}

QString SceneDocument::checkedChange(const SceneItem& item, const std::string& key,
                                     const ParameterValue& value, ParameterChange& change) const {
    if (!contains(item) || !item.hasParameters())
        return tr("%1 no longer exists").arg(QString::fromStdString(pathOf(item, key)));
    const BoundParameter& bound = boundParameter(item, key);
    change.key = key;
    change.newValue = normalised(bound.declaration, value);
    change.oldValue = parameter(item, key);
    return QString::fromStdString(
        ParameterCodec::check(bound.declaration, change.newValue, pathOf(item, key)));
}

SceneItem SceneDocument::addElement(const std::string& section) {
    const SchemaSection& schema = sectionOf(section);
    return addElement(section, nlohmann::json::object(),
                      tr("Add %1").arg(QString::fromStdString(schema.elementLabel)));
}

SceneItem SceneDocument::addElement(const std::string& section, const nlohmann::json& values,
                                    const QString& text) {
    const SchemaSection& schema = sectionOf(section);
    const std::size_t index = schema.elementCount(scene_);
    Scene scratch;
    schema.resize(scratch, 1);
    nlohmann::json element;
    for (const BoundParameter& parameter : schema.parameters)
        element[parameter.declaration.key] = ParameterCodec::toJson(parameter.get(scratch, 0));
    element.update(values);
    undoStack_->push(new InsertElementCommand(*this, section, index, element, text));
    return SceneItem::elementItem(section, index);
}

SceneItem SceneDocument::duplicateElement(const SceneItem& item) {
    if (item.kind != SceneItem::Kind::Element || !contains(item))
        return SceneItem::none();
    nlohmann::json copy = elementJson(item.section, item.element);
    if (copy.contains(kNameKey))
        copy[kNameKey] = copy[kNameKey].get<std::string>() + " copy";
    undoStack_->push(new InsertElementCommand(*this, item.section, item.element + 1, copy,
                                              tr("Duplicate %1").arg(elementName(item))));
    return SceneItem::elementItem(item.section, item.element + 1);
}

void SceneDocument::removeElement(const SceneItem& item) {
    if (item.kind != SceneItem::Kind::Element || !contains(item))
        return;
    undoStack_->push(new RemoveElementCommand(*this, item.section, item.element,
                                              tr("Remove %1").arg(elementName(item))));
}

QString SceneDocument::renameElement(const SceneItem& item, const QString& name) {
    return editParameter(item, kNameKey, name.trimmed().toStdString());
}

// --- Reading ------------------------------------------------------------------------------------

ParameterValue SceneDocument::parameter(const SceneItem& item, const std::string& key) const {
    return boundParameter(item, key).get(scene_, item.element);
}

QString SceneDocument::elementName(const SceneItem& item) const {
    const SchemaSection& schema = sectionOf(item.section);
    if (item.kind != SceneItem::Kind::Element)
        return QString::fromStdString(schema.label);
    if (schema.find(kNameKey) != nullptr)
        return QString::fromStdString(std::get<std::string>(parameter(item, kNameKey)));
    return QStringLiteral("%1 %2")
        .arg(QString::fromStdString(schema.elementLabel))
        .arg(item.element + 1);
}

bool SceneDocument::contains(const SceneItem& item) const {
    if (item.isNone())
        return false;
    const SchemaSection* schema = SceneSchema::findSection(item.section);
    if (schema == nullptr)
        return false;
    if (item.kind == SceneItem::Kind::Element)
        return schema->isArray && item.element < schema->elementCount(scene_);
    if (item.kind == SceneItem::Kind::Group)
        return schema->isArray;
    return !schema->isArray;
}

std::string SceneDocument::pathOf(const SceneItem& item, const std::string& key) {
    return SceneSchema::pathOf(sectionOf(item.section), item.element, key);
}

const SchemaSection& SceneDocument::sectionOf(const std::string& key) {
    const SchemaSection* schema = SceneSchema::findSection(key);
    if (schema == nullptr)
        throw Error(ErrorKind::InvalidInput, "the scene has no section \"" + key + "\"");
    return *schema;
}

const BoundParameter& SceneDocument::boundParameter(const SceneItem& item,
                                                    const std::string& key) const {
    const BoundParameter* bound = sectionOf(item.section).find(key);
    if (bound == nullptr)
        throw Error(ErrorKind::InvalidInput, "the scene has no parameter " + pathOf(item, key));
    return *bound;
}

// --- Raw changes (undo commands) ----------------------------------------------------------------

void SceneDocument::applyParameter(const SceneItem& item, const std::string& key,
                                   const ParameterValue& value) {
    boundParameter(item, key).set(scene_, item.element, value);
    Q_EMIT parameterChanged(item, QString::fromStdString(key));
    Q_EMIT changed();
}

void SceneDocument::insertElement(const std::string& section, std::size_t index,
                                  const nlohmann::json& element) {
    const SchemaSection& schema = sectionOf(section);
    const QString sectionKey = QString::fromStdString(section);
    Q_EMIT elementAboutToBeInserted(sectionKey, static_cast<int>(index));
    schema.insertDefault(scene_, index);
    for (const BoundParameter& parameter : schema.parameters) {
        const auto value = element.find(parameter.declaration.key);
        if (value == element.end())
            continue;
        // The JSON came from this document (a removed or copied element), so it always converts.
        const ParameterCodec::Result converted = ParameterCodec::fromJson(
            parameter.declaration, *value, SceneSchema::pathOf(schema, index, value.key()));
        if (converted.ok())
            parameter.set(scene_, index, converted.value);
    }
    Q_EMIT elementInserted(sectionKey, static_cast<int>(index));
    Q_EMIT changed();
}

void SceneDocument::eraseElement(const std::string& section, std::size_t index) {
    const SchemaSection& schema = sectionOf(section);
    const QString sectionKey = QString::fromStdString(section);
    Q_EMIT elementAboutToBeRemoved(sectionKey, static_cast<int>(index));
    schema.erase(scene_, index);
    Q_EMIT elementRemoved(sectionKey, static_cast<int>(index));
    Q_EMIT changed();
}

nlohmann::json SceneDocument::elementJson(const std::string& section, std::size_t index) const {
    const SchemaSection& schema = sectionOf(section);
    nlohmann::json element = nlohmann::json::object();
    for (const BoundParameter& parameter : schema.parameters)
        element[parameter.declaration.key] = ParameterCodec::toJson(parameter.get(scene_, index));
    return element;
}

} // namespace airtrap
