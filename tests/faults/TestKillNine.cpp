// kill -9 at random moments of bake, post and export: a process that dies without a chance to
// clean up must leave nothing that stops the same command, run again, from giving exactly what
// an undisturbed run gives (docs/CACHE_FORMAT.md "Writing: the atomic protocol"). The moments
// are drawn from a seeded generator; the seed and every moment are logged, and
// AIRTRAP_FAULT_SEED=<seed> replays a run.
#include "faults/FaultTestSupport.h"
#include "support/TestMain.h"

#include <QElapsedTimer>
#include <QTemporaryDir>
#include <algorithm>
#include <functional>
#include <random>

using namespace airtrap::faulttest;
using namespace std::chrono_literals;

namespace {

constexpr int kKills = 20;

std::uint32_t seedOfTheRun() {
    const QByteArray given = qgetenv("AIRTRAP_FAULT_SEED");
    return given.isEmpty() ? std::random_device{}() : given.toUInt();
}

//! How long the command takes undisturbed, in milliseconds: the shortest of three runs, because
//! the first run of a command pays for a cold file cache and can take twice as long as the runs
//! the kills interrupt (which would then mostly fall after the end).
qint64 durationOf(const QStringList& arguments, const std::function<void()>& prepare) {
    qint64 shortest = -1;
    for (int run = 0; run < 3; ++run) {
        prepare();
        QElapsedTimer timer;
        timer.start();
        const CliResult result = runCli(arguments);
        if (result.exitCode != 0)
            return -1;
        shortest = shortest < 0 ? timer.elapsed() : std::min(shortest, timer.elapsed());
    }
    return shortest;
}

} // namespace

class TestKillNine : public QObject {
    Q_OBJECT

    QTemporaryDir root_;
    std::string scene_;
    std::string referenceCache_;
    std::mt19937 random_;

    std::string dir(const std::string& name) const {
        return root_.path().toStdString() + "/" + name;
    }

    //! Kills `command` 20 times at moments spread over its undisturbed duration, each time
    //! running it again to the end and comparing `result` with `reference`. `prepare` gives the
    //! command its input afresh before each kill.
    void killAndRerun(const QStringList& command, const std::function<void()>& prepare,
                      const std::string& result, const std::string& reference) {
        const qint64 duration = durationOf(command, prepare);
        QVERIFY2(duration >= 0, "the undisturbed run failed");
        QVERIFY_SAME_AS(result, reference);
        // Up to a little beyond the end: a kill while the last file is renamed counts too.
        std::uniform_int_distribution<qint64> moment(0, duration + duration / 10);
        int killed = 0;
        for (int kill = 0; kill < kKills; ++kill) {
            prepare();
            const qint64 at = moment(random_);
            const StoppedRun run = runAndSignal(command, std::chrono::milliseconds(at), SIGKILL);
            killed += run.stoppedEarly ? 1 : 0;
            qInfo("kill %d at %lld ms of %lld: %s", kill + 1, at, duration,
                  run.stoppedEarly ? "killed" : "had finished");
            const CliResult rerun = runCli(command);
            QCOMPARE_EXIT(rerun, 0);
            QVERIFY_SAME_AS(result, reference);
            const std::vector<std::string> temporaries = temporariesUnder(result);
            QVERIFY2(temporaries.empty(), temporaries.empty() ? "" : temporaries.front().c_str());
        }
        // Most moments must fall inside the run, or the test proves little.
        QVERIFY2(killed >= kKills / 2,
                 qPrintable(
                     QString("only %1 of %2 kills hit a running process").arg(killed).arg(kKills)));
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(root_.isValid());
        const std::uint32_t seed = seedOfTheRun();
        qInfo("kill moments drawn with AIRTRAP_FAULT_SEED=%u", seed);
        random_.seed(seed);
        scene_ = dir("bubbles.json");
        // Long enough in frames for most kills to land mid-bake; post and export take 4 of them.
        writeText(scene_, bubbleSceneText(80));
        referenceCache_ = dir("reference");
        QCOMPARE_EXIT(runCli(args({"bake", scene_, "--out", referenceCache_, "-q"})), 0);
    }

    void aKilledBakeResumesToTheSameFrames() {
        const std::string cache = dir("bake");
        killAndRerun(
            args({"bake", scene_, "--out", cache, "--resume", "-q"}),
            [&] { fs::remove_all(cache); }, cache, referenceCache_);
    }

    void aKilledPostIsFinishedByTheNextPost() {
        const std::string reference = dir("post-reference");
        copyFolder(referenceCache_, reference);
        const QStringList frames = {"--frames", "1:4"};
        QCOMPARE_EXIT(runCli(args({"post", reference, "-q"}) + frames), 0);
        const std::string cache = dir("post");
        copyFolder(referenceCache_, cache);
        killAndRerun(
            args({"post", cache, "-q", "--threads", "2"}) + frames,
            [&] { fs::remove_all(cache + "/post"); }, cache, reference);
    }

    void aKilledExportIsRedoneByTheNextExport_data() {
        QTest::addColumn<QString>("format");
        QTest::newRow("obj") << "obj";
        QTest::newRow("vdb") << "vdb";
        QTest::newRow("ply") << "ply";
    }

    void aKilledExportIsRedoneByTheNextExport() {
        QFETCH(QString, format);
        const std::string cache = dir("export-cache");
        if (!fs::exists(cache + "/post")) {
            copyFolder(referenceCache_, cache);
            QCOMPARE_EXIT(runCli(args({"post", cache, "-q", "--frames", "1:4"})), 0);
        }
        const QStringList export_ = args(
            {"export", cache, "--format", format.toStdString(), "--frames", "1:4", "-q", "--out"});
        const std::string reference = dir("export-reference-" + format.toStdString());
        QCOMPARE_EXIT(runCli(export_ + args({reference})), 0);
        const std::string out = dir("export-" + format.toStdString());
        killAndRerun(
            export_ + args({out}), [&] { fs::remove_all(out); }, out, reference);
    }
};

AIRTRAP_TEST_GUILESS(TestKillNine)
#include "TestKillNine.moc"
