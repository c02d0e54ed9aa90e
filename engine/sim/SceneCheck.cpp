#include "sim/SceneCheck.h"

#include "core/Error.h"
#include "sim/BodyPlacementCheck.h"

namespace airtrap {

SceneIssues SceneCheck::run(const Scene& scene) {
    SceneIssues issues = SceneValidator::check(scene);
    // Bodies are built only from fields in range: with bad fields they would only add noise.
    if (!issues.ok())
        return issues;
    const std::string source = scene.sourcePath.empty() ? "scene" : scene.sourcePath;
    const BodyPlacementCheck::Findings findings = BodyPlacementCheck::run(scene);
    for (const std::string& message : findings.errors)
        issues.errors.push_back(message.starts_with(source) ? message : source + ": " + message);
    for (const std::string& message : findings.warnings)
        issues.warnings.push_back(source + ": " + message);
    for (const std::string& message : findings.notes)
        issues.notes.push_back(source + ": " + message);
    return issues;
}

std::vector<std::string> validateScene(const Scene& scene, std::vector<std::string>* notes) {
    SceneIssues issues = SceneCheck::run(scene);
    if (!issues.ok()) {
        std::string message;
        for (const std::string& line : issues.errors)
            message += (message.empty() ? "" : "\n") + line;
        throw Error(ErrorKind::InvalidScene, message);
    }
    if (notes != nullptr)
        *notes = std::move(issues.notes);
    return issues.warnings;
}

} // namespace airtrap
