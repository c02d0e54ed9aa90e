#include "BubbleCensusReport.h"

#include "scene/SceneJson.h"

#include <cstdio>
#include <string>

namespace airtrap::cli {
namespace {

nlohmann::ordered_json frameJson(const BubbleCensusFrame& row) {
    return {{"frame", row.frame},
            {"time", row.time},
            {"alive", row.alive},
            {"in_water", row.inWater},
            {"floating", row.floating},
            {"airborne", row.airborne},
            {"mean_rise_speed_in_water", row.meanRiseSpeedInWater},
            {"mean_slip_speed_in_water", row.meanSlipSpeedInWater},
            {"mean_target_rise_speed", row.meanTargetRiseSpeed},
            {"created", row.created},
            {"deleted", row.deleted},
            {"books_balance", row.booksBalance}};
}

nlohmann::ordered_json deletedJson(const BubbleTally& tally) {
    nlohmann::ordered_json counts = nlohmann::ordered_json::object();
    for (int rule = 0; rule < BubbleTally::RuleCount; ++rule)
        counts[std::string(BubbleTally::kRuleNames[rule])] = tally.deleted[rule];
    return counts;
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", 100.0 * share);
    return text;
}

} // namespace

BubbleCensusReport::BubbleCensusReport(const FrameCache& cache, std::ostream& notes)
    : census_(sceneFromJson(cache.manifest().scene, cache.manifestPath())) {
    for (int frame : cache.frames()) {
        std::string problem;
        if (const std::optional<FrameData> data = cache.readIntactFrame(frame, problem))
            census_.add(*data);
        else
            notes << "note: skipping a damaged frame: " << problem << '\n';
    }
}

double BubbleCensusReport::inWaterSecondHalf() const {
    const auto& frames = census_.frames();
    return frames.empty() ? 0.0 : census_.meanInWaterFrom(frames.back().frame / 2 + 1);
}

nlohmann::ordered_json BubbleCensusReport::toJson() const {
    const BubbleCensusTotals& t = census_.totals();
    nlohmann::ordered_json frames = nlohmann::ordered_json::array();
    for (const BubbleCensusFrame& row : census_.frames())
        frames.push_back(frameJson(row));
    nlohmann::ordered_json totals = {
        {"frames", t.frames},
        {"bubble_frames", t.bubbleFrames},
        {"in_water", t.inWater},
        {"floating", t.floating},
        {"airborne", t.airborne},
        {"in_water_share", t.inWaterShare()},
        {"floating_share", t.floatingShare()},
        {"airborne_share", t.airborneShare()},
        {"mean_rise_speed_in_water", t.meanRiseSpeedInWater},
        {"mean_slip_speed_in_water", t.meanSlipSpeedInWater},
        {"mean_target_rise_speed", t.meanTargetRiseSpeed},
        {"mean_depth_at_creation", t.meanDepthAtCreation},
        {"first_seen",
         {{"in_water", t.newInWater}, {"floating", t.newFloating}, {"airborne", t.newAirborne}}},
        {"mean_lifetime", t.meanLifetime},
        {"created", t.created},
        {"alive", t.alive},
        {"deleted", deletedJson(t.deleted)},
        {"surfaced_young", t.deleted.surfacedYoung},
        {"in_water_per_frame_second_half", inWaterSecondHalf()},
        {"books_balance", t.booksBalance}};
    return {{"rule", "26 probes at r + spacing/2; wet: water within one spacing; in water >= 13 "
                     "wet, airborne < 6.5"},
            {"frames", frames},
            {"totals", totals}};
}

void BubbleCensusReport::printText(std::ostream& out) const {
    out << "frame  alive  water  float  air   rise m/s  slip m/s  target m/s  made  gone\n";
    for (const BubbleCensusFrame& row : census_.frames()) {
        char line[128];
        std::snprintf(line, sizeof line,
                      "%5d  %5d  %5d  %5d  %4d  %8.3f  %8.3f  %10.3f  %4d  %4llu%s\n", row.frame,
                      row.alive, row.inWater, row.floating, row.airborne, row.meanRiseSpeedInWater,
                      row.meanSlipSpeedInWater, row.meanTargetRiseSpeed, row.created,
                      (unsigned long long)row.deleted, row.booksBalance ? "" : "  books off");
        out << line;
    }
    const BubbleCensusTotals& t = census_.totals();
    out << "bubble-frames " << t.bubbleFrames << ": in water " << percent(t.inWaterShare())
        << ", floating " << percent(t.floatingShare()) << ", airborne "
        << percent(t.airborneShare()) << '\n';
    char line[256];
    std::snprintf(line, sizeof line,
                  "rise in water %.3f m/s, %.3f relative to the water (target %.3f); first seen: "
                  "depth %.3f m, %llu in water, %llu floating, %llu airborne; lifetime %.2f s "
                  "over %llu ended\n",
                  t.meanRiseSpeedInWater, t.meanSlipSpeedInWater, t.meanTargetRiseSpeed,
                  t.meanDepthAtCreation, (unsigned long long)t.newInWater,
                  (unsigned long long)t.newFloating, (unsigned long long)t.newAirborne,
                  t.meanLifetime, (unsigned long long)t.ended);
    out << line;
    std::snprintf(line, sizeof line, "in water per frame over the second half: %.1f\n",
                  inWaterSecondHalf());
    out << line << "made " << t.created << " = alive " << t.alive << " + deleted "
        << t.deleted.deletedTotal() << " (";
    for (int rule = 0; rule < BubbleTally::RuleCount; ++rule)
        out << (rule ? ", " : "") << BubbleTally::kRuleNames[rule] << ' '
            << t.deleted.deleted[rule];
    out << "; surfaced younger than 0.1 s " << t.deleted.surfacedYoung << ")"
        << (t.booksBalance ? "" : "; the books do not balance in every frame") << '\n';
}

} // namespace airtrap::cli
