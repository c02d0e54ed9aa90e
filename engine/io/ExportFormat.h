#pragma once
// The file formats of an export (docs/CLI.md "export"), and their names as the command line, the
// editor's log and the error messages write them: declared here once.
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace airtrap {

enum class ExportFormat { Ply, Obj, Vdb };

//! Every format, in the order help texts list them.
constexpr std::array<ExportFormat, 3> kExportFormats = {ExportFormat::Obj, ExportFormat::Vdb,
                                                        ExportFormat::Ply};

//! "ply", "obj" or "vdb": also the files' extension.
constexpr std::string_view exportFormatName(ExportFormat format) {
    switch (format) {
    case ExportFormat::Ply:
        return "ply";
    case ExportFormat::Vdb:
        return "vdb";
    case ExportFormat::Obj:
        break;
    }
    return "obj";
}

//! The format named `name` (as exportFormatName() writes it); none for any other text.
constexpr std::optional<ExportFormat> exportFormatNamed(std::string_view name) {
    for (ExportFormat format : kExportFormats)
        if (exportFormatName(format) == name)
            return format;
    return std::nullopt;
}

//! "obj, vdb or ply": the formats for a message that lists what is expected.
inline std::string exportFormatList() {
    std::string list;
    for (std::size_t k = 0; k < kExportFormats.size(); ++k) {
        if (k > 0)
            list += k + 1 == kExportFormats.size() ? " or " : ", ";
        list += exportFormatName(kExportFormats[k]);
    }
    return list;
}

} // namespace airtrap
