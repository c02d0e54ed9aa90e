// Ctrl-C (and SIGTERM, what a scheduler sends) during each stage, with one and two threads where
// the stage has threads: exit 130 (75 for a bake stopped by SIGUSR1) with the way on, a cache that
// checks intact, every finished frame kept, and the same command run again finishing to what an
// undisturbed run gives (docs/CLI.md "Exit codes").
#include "faults/FaultTestSupport.h"
#include "support/TestMain.h"

#include <QTemporaryDir>

using namespace airtrap::faulttest;

class TestInterrupts : public QObject {
    Q_OBJECT

    QTemporaryDir root_;
    std::string scene_;
    std::string referenceCache_; //!< baked, and posted for frames 1 to kPostFrames
    std::string caseDir_;

    static constexpr int kFrames = 240;
    static constexpr int kPostFrames = 12;

    std::string dir(const std::string& name) const {
        return root_.path().toStdString() + "/" + name;
    }
    std::string cache() const { return caseDir_ + "/cache"; }

    QStringList postFrames() const {
        return args({"--frames", "1:" + std::to_string(kPostFrames)});
    }

    //! Every frame and result the stopped run left is whole: check finds nothing damaged.
    void checkIntact(const std::string& cacheDir) {
        const CliResult check = runCli(args({"check", cacheDir}));
        QCOMPARE_EXIT(check, 0);
        const std::vector<std::string> temporaries = temporariesUnder(caseDir_);
        QVERIFY2(temporaries.empty(), temporaries.empty() ? "" : temporaries.front().c_str());
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(root_.isValid());
        scene_ = dir("bubbles.json");
        writeText(scene_, bubbleSceneText(kFrames));
        referenceCache_ = dir("reference");
        QCOMPARE_EXIT(runCli(args({"bake", scene_, "--out", referenceCache_, "-q"})), 0);
        QCOMPARE_EXIT(runCli(args({"post", referenceCache_, "-q"}) + postFrames()), 0);
        caseDir_ = dir("case");
    }

    void init() {
        fs::remove_all(caseDir_);
        fs::create_directories(caseDir_);
    }

    void aStoppedBakeKeepsItsFramesAndResumes_data() {
        QTest::addColumn<int>("threads");
        QTest::addColumn<int>("signal");
        QTest::newRow("Ctrl-C, 1 thread") << 1 << SIGINT;
        QTest::newRow("Ctrl-C, 2 threads") << 2 << SIGINT;
        QTest::newRow("SIGTERM, 2 threads") << 2 << SIGTERM;
        // A scheduler's warning before a time limit or a preemption (docs/FARM.md): exit 75.
        QTest::newRow("SIGUSR1, 2 threads") << 2 << SIGUSR1;
    }

    void aStoppedBakeKeepsItsFramesAndResumes() {
        QFETCH(int, threads);
        QFETCH(int, signal);
        const QStringList bake = args(
            {"bake", scene_, "--out", cache(), "--resume", "--threads", std::to_string(threads)});
        const StoppedRun run = signalAtMark(bake, "frame 3/", signal);
        QVERIFY2(run.stoppedEarly, run.err.constData());
        QVERIFY2(run.exitCode == (signal == SIGUSR1 ? 75 : 130), run.err.constData());
        QVERIFY2(run.err.contains("resume with: airtrap-cli bake"), run.err.constData());
        QCOMPARE(readJson(cache() + "/manifest.json").at("status").get<std::string>(),
                 std::string("stopped"));
        checkIntact(cache());
        const std::vector<std::string> kept = filesUnder(cache());
        QVERIFY(kept.size() > 3 && kept.size() < std::size_t(kFrames));
        for (const std::string& file : kept)
            if (file.ends_with(".atf"))
                QVERIFY2(sameContent(cache() + "/" + file, referenceCache_ + "/" + file),
                         file.c_str());
        QCOMPARE_EXIT(runCli(bake + args({"-q"})), 0);
        fs::remove_all(referenceCache_ + "-frames");
        copyFolder(referenceCache_, referenceCache_ + "-frames");
        fs::remove_all(referenceCache_ + "-frames/post");
        QVERIFY_SAME_AS(cache(), referenceCache_ + "-frames");
    }

    void aStoppedPostKeepsItsResultsAndFinishes_data() {
        QTest::addColumn<int>("threads");
        QTest::newRow("1 thread") << 1;
        QTest::newRow("2 threads") << 2;
    }

    void aStoppedPostKeepsItsResultsAndFinishes() {
        QFETCH(int, threads);
        copyFolder(referenceCache_, cache());
        fs::remove_all(cache() + "/post");
        const QStringList post =
            args({"post", cache(), "--threads", std::to_string(threads)}) + postFrames();
        // Stopped several times while frames are made side by side: on two threads Ctrl-C once
        // crashed post in 5 of 9 runs.
        for (int stop = 0; stop < 3; ++stop) {
            fs::remove_all(cache() + "/post");
            const StoppedRun run = signalAtMark(post, "post: 2 of", SIGINT);
            QVERIFY2(run.stoppedEarly, run.err.constData());
            QVERIFY2(run.exitCode == 130, run.err.constData());
            QVERIFY2(run.err.contains("run post again to finish"), run.err.constData());
            checkIntact(cache());
        }
        QCOMPARE_EXIT(runCli(post + args({"-q"})), 0);
        QVERIFY_SAME_AS(cache(), referenceCache_);
    }

    //! The export has no threads of its own: one run per format, stopped at its progress line.
    void aStoppedExportKeepsWholeFilesAndIsRedone_data() {
        QTest::addColumn<QString>("format");
        QTest::newRow("obj") << "obj";
        QTest::newRow("vdb") << "vdb";
        QTest::newRow("ply") << "ply";
    }

    void aStoppedExportKeepsWholeFilesAndIsRedone() {
        QFETCH(QString, format);
        // PLY needs no post results: it writes every frame, which gives Ctrl-C time to land.
        const QStringList frames = format == "ply" ? QStringList() : postFrames();
        const QStringList export_ =
            args({"export", referenceCache_, "--format", format.toStdString()}) + frames +
            args({"--out"});
        const std::string reference = dir("export-" + format.toStdString());
        QCOMPARE_EXIT(runCli(export_ + args({reference, "-q"})), 0);
        const std::string out = caseDir_ + "/out";
        const StoppedRun run = signalAtMark(export_ + args({out}), "export: 2 of", SIGINT);
        QVERIFY2(run.stoppedEarly, run.err.constData());
        QVERIFY2(run.exitCode == 130, run.err.constData());
        QVERIFY2(run.err.contains("stopped after"), run.err.constData());
        const std::vector<std::string> temporaries = temporariesUnder(out);
        QVERIFY2(temporaries.empty(), temporaries.empty() ? "" : temporaries.front().c_str());
        std::size_t sequenceFiles = 0;
        for (const std::string& file : filesUnder(out)) {
            if (file == "export.json")
                continue; // lists what the stopped run wrote: counted below
            ++sequenceFiles;
            QVERIFY2(sameContent(out + "/" + file, reference + "/" + file), file.c_str());
        }
        // The listing names exactly the files the stopped run left, no frame it did not write.
        std::size_t listed = 0;
        const nlohmann::json listing = readJson(out + "/export.json");
        for (const auto& entry : listing.at("sequences"))
            listed += entry.at("frames").size();
        QCOMPARE(listed, sequenceFiles);
        QCOMPARE_EXIT(runCli(export_ + args({out, "-q"})), 0);
        QVERIFY_SAME_AS(out, reference);
    }
};

AIRTRAP_TEST_GUILESS(TestInterrupts)
#include "TestInterrupts.moc"
