#include "CheckCommand.h"

#include "cache/FrameCache.h"
#include "core/Error.h"
#include "post/PostStore.h"
#include "post/SubgridStore.h"

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

} // namespace

void CheckCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("check", "Verify every frame, post result and sub-grid file of "
                                          "a cache, and say how to repair what is damaged");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
}

ExitCode CheckCommand::run() {
    // A damaged manifest is reported by open() itself (exit 3, naming the field).
    const FrameCache cache = FrameCache::open(cacheDir_);
    bool damaged = report("cache frames", checkFrames(cache),
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
    if (!findings.damaged.empty())
        std::cout << "  to repair: " << wayOn << '\n';
    return !findings.damaged.empty();
}

} // namespace airtrap::cli
