#include "post/ManifestJson.h"

#include "core/AtomicFile.h"
#include "core/Error.h"

#include <filesystem>

namespace airtrap {

std::optional<nlohmann::json> readManifestJson(const std::string& path, const std::string& format,
                                               int maxVersion) {
    if (!std::filesystem::exists(path))
        return std::nullopt;
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(bytes.begin(), bytes.end());
    } catch (const nlohmann::json::exception& error) {
        throw Error(ErrorKind::CacheCorrupt, path + ": not valid JSON (" + error.what() + ")");
    }
    if (!json.is_object() || json.value("format", "") != format)
        throw Error(ErrorKind::CacheCorrupt, path + ": field 'format' is not \"" + format + "\"");
    if (json.value("format_version", 0) > maxVersion)
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": format_version " + json["format_version"].dump() +
                        ", this build reads " + std::to_string(maxVersion) + " at most");
    return json;
}

void writeManifestJson(const std::string& path, const std::string& format, int version,
                       const nlohmann::json& settings, const nlohmann::json& frames) {
    const nlohmann::json json = {{"format", format},
                                 {"format_version", version},
                                 {"creator", "Airtrap " AIRTRAP_VERSION},
                                 {"settings", settings},
                                 {"frames", frames}};
    AtomicFile::write(path, json.dump(2) + "\n");
}

void createResultFolder(const std::string& dir) {
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error)
        throw Error(ErrorKind::Io,
                    AtomicFile::errorMessage("cannot create folder", dir, error.value()));
}

} // namespace airtrap
