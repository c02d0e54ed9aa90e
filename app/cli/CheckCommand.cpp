#include "CheckCommand.h"

#include "cache/FrameCache.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "post/PostStore.h"
#include "post/SubgridStore.h"

#include <filesystem>
#include <iostream>

namespace airtrap::cli {

namespace {

//! Runs `read`; a CacheCorrupt error is a finding, any other error propagates (an unreadable
//! file is not evidence of damage).
template <class Read>
void verifyOne(Read&& read, std::vector<std::string>& damaged) {
    try {
        read();
    } catch (const Error& error) {
        if (error.kind() != ErrorKind::CacheCorrupt)
            throw;
        damaged.push_back(error.what());
    }
}

//! A list that is gone while result files are still there: a first post run stopped before it
//! wrote its list, or the list was deleted. Not damage (nothing listed is lost), but nothing
//! vouches for those files: post makes them again. Empty when the list is there or nothing is.
std::string lostList(const std::string& list, const std::vector<std::string>& kinds) {
    std::error_code error;
    if (std::filesystem::exists(list, error))
        return {};
    std::size_t results = 0;
    const std::filesystem::path folder = std::filesystem::path(list).parent_path();
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error)) {
        const std::string name = it->path().filename().string();
        for (const std::string& kind : kinds)
            results += name.starts_with(kind) && !AtomicFile::isTemporaryName(name);
    }
    if (results == 0)
        return {};
    return list + ": missing, while the folder holds " + std::to_string(results) +
           " result file(s); they are not listed, and `airtrap-cli post` makes them again";
}

} // namespace

void CheckCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("check", "Verify every frame, post result and sub-grid file of "
                                          "a cache, and say how to repair what is damaged");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
}

ExitCode CheckCommand::run() {
    // A damaged manifest is reported by open() itself (exit 3, naming the field).
    const FrameCache cache = FrameCache::open(cacheDir_);
    bool damaged = report("cache manifest", checkManifest(cache),
                          "bake the scene again with the command line that made the cache and "
                          "--resume: it writes the manifest's record of the scene again");
    damaged |= report("cache frames", checkFrames(cache),
                      "bake the scene again with the command line that made the cache and "
                      "--resume: it continues from the last frame before the first damaged "
                      "one");
    damaged |= report("post results", checkPostResults(),
                      "run `airtrap-cli post " + cacheDir_ + "`: it makes them again");
    damaged |= report("sub-grid bubble frames", checkSubgridFiles(),
                      "run `airtrap-cli post " + cacheDir_ + "`: it makes them again");
    if (damaged)
        throw Error(ErrorKind::CacheCorrupt, cacheDir_ + ": damaged files found (above)");
    std::cout << "check: " << cacheDir_ << " is intact\n";
    return ExitCode::Success;
}

CheckCommand::Findings CheckCommand::checkManifest(const FrameCache& cache) const {
    Findings findings;
    findings.verified = 1;
    if (std::string damage = cache.recordedSceneDamage(); !damage.empty())
        findings.damaged.push_back(std::move(damage));
    return findings;
}

CheckCommand::Findings CheckCommand::checkFrames(const FrameCache& cache) const {
    Findings findings;
    for (const int frame : cache.frames()) {
        ++findings.verified;
        verifyOne([&] { cache.readFrame(frame); }, findings.damaged);
    }
    return findings;
}

CheckCommand::Findings CheckCommand::checkPostResults() const {
    Findings findings;
    verifyOne(
        [&] {
            const PostStore store = PostStore::open(cacheDir_);
            findings.verified = int(store.frames().size());
            findings.damaged = store.verify();
            const std::string list = store.directory() + "/" + PostStore::kManifestName;
            if (std::string lost = lostList(list, {"water_", "fluid_"}); !lost.empty())
                findings.notes.push_back(std::move(lost));
        },
        findings.damaged);
    return findings;
}

CheckCommand::Findings CheckCommand::checkSubgridFiles() const {
    Findings findings;
    verifyOne(
        [&] {
            const SubgridStore store = SubgridStore::open(cacheDir_);
            for (const int frame : store.frames()) {
                ++findings.verified;
                verifyOne([&] { store.readFrame(frame); }, findings.damaged);
            }
            const std::string list = store.directory() + "/" + SubgridStore::kManifestName;
            if (std::string lost = lostList(list, {"subgrid_"}); !lost.empty())
                findings.notes.push_back(std::move(lost));
        },
        findings.damaged);
    return findings;
}

bool CheckCommand::report(const char* what, const Findings& findings,
                          const std::string& wayOn) const {
    std::cout << what << ": " << findings.verified << " verified, " << findings.damaged.size()
              << " damaged\n";
    for (const std::string& problem : findings.damaged)
        std::cout << "  damaged: " << problem << '\n';
    for (const std::string& note : findings.notes)
        std::cout << "  note: " << note << '\n';
    if (!findings.damaged.empty())
        std::cout << "  to repair: " << wayOn << '\n';
    return !findings.damaged.empty();
}

} // namespace airtrap::cli
