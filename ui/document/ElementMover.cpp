#include "document/ElementMover.h"

#include "document/SceneDocument.h"
#include "scene/ParameterCodec.h"

namespace airtrap {

std::vector<std::string> ElementMover::positionKeys(const SceneItem& item) {
    if (item.kind != SceneItem::Kind::Element)
        return {};
    if (item.section == "bodies" || item.section == "emitters")
        return {"position"};
    if (item.section == "obstacles")
        return {"center"};
    if (item.section == "fluid_blocks")
        return {"min", "max"};
    return {};
}

void ElementMover::begin(const SceneItem& item) {
    item_ = item;
    origin_.clear();
    for (const std::string& key : positionKeys(item))
        origin_.emplace_back(key, std::get<Vec3d>(document_.parameter(item, key)));
    session_ = origin_.empty() ? 0 : document_.newDragSession();
}

QString ElementMover::moveTo(int axis, double offset) {
    if (!isMoving())
        return {};
    Vec3d step = Vec3d::Zero();
    step[axis] = offset;
    std::vector<std::pair<std::string, ParameterValue>> values;
    for (const auto& [key, start] : origin_)
        values.emplace_back(key, ParameterValue(Vec3d(start + step)));
    static constexpr const char* kAxisNames[] = {"x", "y", "z"};
    const QString text = QObject::tr("Move %1 along %2 by %3 m")
                             .arg(document_.elementName(item_), QLatin1String(kAxisNames[axis]),
                                  QString::fromStdString(ParameterCodec::formatNumber(offset)));
    return document_.editParameters(item_, values, session_, text);
}

void ElementMover::end() {
    session_ = 0;
    origin_.clear();
}

} // namespace airtrap
