// A full disk, a read-only or forbidden output and a file-size limit met by each stage that
// writes: bake, post and the three exports. Each case checks the exit code and the message
// naming the path and the reason, that no temporary file is left, that nothing written before
// the fault is lost, and that the same command run again once the fault is gone gives what an
// undisturbed run gives (docs/CLI.md "Exit codes", docs/CACHE_FORMAT.md "Writing").
#include "faults/FaultTestSupport.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <sys/resource.h>
#include <unistd.h>

using namespace airtrap::faulttest;

namespace {

//! One stage that writes, and where it reads and writes.
struct Stage {
    std::string name;   //!< "bake", "post", "export obj", …
    std::string format; //!< the export's format; empty for bake and post

    bool isExport() const { return !format.empty(); }
};

const std::vector<Stage>& stages() {
    static const std::vector<Stage> all = {{"bake", ""},
                                           {"post", ""},
                                           {"export obj", "obj"},
                                           {"export vdb", "vdb"},
                                           {"export ply", "ply"}};
    return all;
}

const Stage& stageNamed(const QString& name) {
    for (const Stage& stage : stages())
        if (QString::fromStdString(stage.name) == name)
            return stage;
    throw std::logic_error("no stage " + name.toStdString());
}

} // namespace

class TestDiskFaults : public QObject {
    Q_OBJECT

    QTemporaryDir root_;
    std::string scene_;
    std::string referenceFrames_; //!< baked without a fault
    std::string referenceCache_;  //!< the same, posted
    std::string caseDir_;

    std::string reference(const Stage& stage) const {
        if (stage.name == "bake")
            return referenceFrames_;
        return stage.isExport() ? root_.path().toStdString() + "/reference-" + stage.format
                                : referenceCache_;
    }
    std::string cache() const { return caseDir_ + "/cache"; }
    std::string out() const { return caseDir_ + "/out"; }

    //! Where the stage writes: the faults act there only.
    std::string written(const Stage& stage) const {
        if (stage.name == "post")
            return cache() + "/post";
        return stage.isExport() ? out() : cache();
    }
    //! What the stage leaves, to compare with the reference.
    std::string result(const Stage& stage) const { return stage.isExport() ? out() : cache(); }

    //! The one command line of the stage, the same before and after the fault (a bake resumes).
    QStringList command(const Stage& stage) const {
        if (stage.name == "bake")
            return args({"bake", scene_, "--out", cache(), "--resume", "-q"});
        if (stage.name == "post")
            return args({"post", cache(), "-q"});
        return args({"export", cache(), "--format", stage.format, "--out", out(), "-q"});
    }

    //! The stage's input: nothing for a bake, the baked cache for post, everything for export.
    void prepare(const Stage& stage) {
        fs::remove_all(caseDir_);
        fs::create_directories(caseDir_);
        if (stage.name == "bake")
            return;
        copyFolder(referenceCache_, cache());
        if (stage.name == "post")
            fs::remove_all(cache() + "/post");
    }

    //! What the stage wrote in the undisturbed run.
    std::string referenceOutput(const Stage& stage) const {
        return stage.name == "post" ? referenceCache_ + "/post" : reference(stage);
    }

    //! How many bytes the stage writes in an undisturbed run.
    std::uintmax_t bytesWritten(const Stage& stage) const {
        const std::string dir = referenceOutput(stage);
        std::uintmax_t total = 0;
        for (const std::string& file : filesUnder(dir))
            total += fs::file_size(dir + "/" + file);
        return total;
    }

    //! Nothing written before the fault is lost, and nothing half-written is left.
    void checkNothingLost(const Stage& stage) {
        const std::vector<std::string> temporaries = temporariesUnder(caseDir_);
        QVERIFY2(temporaries.empty(), temporaries.empty() ? "" : temporaries.front().c_str());
        if (stage.isExport()) {
            QVERIFY_SAME_AS(cache(), referenceCache_);
            return;
        }
        // Every frame or result that was written is whole and listed: check finds no damage.
        if (fs::exists(cache() + "/manifest.json")) {
            const CliResult check = runCli(args({"check", cache()}));
            QCOMPARE_EXIT(check, 0);
        }
        for (const std::string& file : filesUnder(cache()))
            if (file.ends_with(".atf"))
                QVERIFY2(sameContent(cache() + "/" + file, referenceFrames_ + "/" + file),
                         file.c_str());
    }

    void checkRerunCompletes(const Stage& stage) {
        const CliResult rerun = runCli(command(stage));
        QCOMPARE_EXIT(rerun, 0);
        QVERIFY_SAME_AS(result(stage), reference(stage));
    }

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(root_.isValid());
        const std::string dir = root_.path().toStdString();
        scene_ = dir + "/bubbles.json";
        writeText(scene_, bubbleSceneText(6));
        referenceFrames_ = dir + "/reference-frames";
        QCOMPARE_EXIT(runCli(args({"bake", scene_, "--out", referenceFrames_, "-q"})), 0);
        referenceCache_ = dir + "/reference";
        copyFolder(referenceFrames_, referenceCache_);
        QCOMPARE_EXIT(runCli(args({"post", referenceCache_, "-q"})), 0);
        for (const Stage& stage : stages())
            if (stage.isExport())
                QCOMPARE_EXIT(runCli(args({"export", referenceCache_, "--format", stage.format,
                                           "--out", reference(stage), "-q"})),
                              0);
        caseDir_ = dir + "/case";
    }

    void aFullDiskStopsTheStageKeepingWhatWasWritten_data() {
        QTest::addColumn<QString>("stage");
        QTest::addColumn<double>("share"); // of the stage's output written before the disk fills
        for (const Stage& stage : stages())
            for (const double share : {0.0, 0.3, 0.7}) {
                const std::string row = stage.name + ", full after " +
                                        std::to_string(int(share * 100)) + " % of its output";
                QTest::newRow(row.c_str()) << QString::fromStdString(stage.name) << share;
            }
    }

    void aFullDiskStopsTheStageKeepingWhatWasWritten() {
        QFETCH(QString, stage);
        QFETCH(double, share);
        const Stage& writing = stageNamed(stage);
        prepare(writing);
        const DiskFault full{written(writing), (long long)(share * double(bytesWritten(writing)))};
        const CliResult result = runCliWith(full, command(writing));
        QCOMPARE_EXIT(result, 4);
        QVERIFY_CONTAINS(result.err, "disk full");
        QVERIFY_CONTAINS(result.err, written(writing));
        if (writing.name == "bake")
            QVERIFY_CONTAINS(result.err, "continue with --resume");
        checkNothingLost(writing);
        checkRerunCompletes(writing);
    }

    void anOutputThatCannotBeWrittenIsNamed_data() {
        QTest::addColumn<QString>("stage");
        QTest::addColumn<QString>("error");
        QTest::addColumn<QString>("reason");
        for (const Stage& stage : stages()) {
            const QString name = QString::fromStdString(stage.name);
            QTest::newRow(qPrintable(name + ", read-only")) << name << "EROFS"
                                                            << "read-only file system";
            QTest::newRow(qPrintable(name + ", forbidden")) << name << "EACCES"
                                                            << "permission denied";
        }
    }

    void anOutputThatCannotBeWrittenIsNamed() {
        QFETCH(QString, stage);
        QFETCH(QString, error);
        QFETCH(QString, reason);
        const Stage& writing = stageNamed(stage);
        prepare(writing);
        const DiskFault refusing{written(writing), -1, error.toStdString()};
        const CliResult result = runCliWith(refusing, command(writing));
        QCOMPARE_EXIT(result, 4);
        QVERIFY_CONTAINS(result.err, reason.toStdString());
        QVERIFY_CONTAINS(result.err, written(writing));
        checkNothingLost(writing);
        checkRerunCompletes(writing);
    }

    void aFileSizeLimitStopsTheStageWithItsReason_data() {
        QTest::addColumn<QString>("stage");
        for (const Stage& stage : stages())
            QTest::newRow(stage.name.c_str()) << QString::fromStdString(stage.name);
    }

    void aFileSizeLimitStopsTheStageWithItsReason() {
        QFETCH(QString, stage);
        const Stage& writing = stageNamed(stage);
        prepare(writing);
        // Below the size of the stage's largest file, above its smallest list: some writes
        // succeed, then one meets the limit.
        std::uintmax_t largest = 0;
        const std::string dir = referenceOutput(writing);
        for (const std::string& file : filesUnder(dir))
            largest = std::max(largest, fs::file_size(dir + "/" + file));
        const auto limit = rlim_t(largest / 2);
        const CliResult result = runCli(command(writing), [limit] {
            std::signal(SIGXFSZ, SIG_DFL);
            const rlimit small{limit, limit};
            ::setrlimit(RLIMIT_FSIZE, &small);
        });
        QCOMPARE_EXIT(result, 4);
        QVERIFY_CONTAINS(result.err, "file-size limit reached");
        checkNothingLost(writing);
        checkRerunCompletes(writing);
    }

    //! The real thing where it can be made: the stage writes onto a small tmpfs mounted in a
    //! mount namespace of its own (`unshare --mount`, which needs CAP_SYS_ADMIN). What the stage
    //! left there is copied out before the namespace ends, then checked like the cases above.
    void aRealFullDiskStopsTheStage_data() { aFileSizeLimitStopsTheStageWithItsReason_data(); }

    void aRealFullDiskStopsTheStage() {
        QFETCH(QString, stage);
        const Stage& writing = stageNamed(stage);
        prepare(writing);
        const std::string kept = caseDir_ + "-kept";
        fs::remove_all(kept);
        fs::create_directories(kept);
        fs::create_directories(written(writing));
        const std::uintmax_t kilobytes = std::max<std::uintmax_t>(bytesWritten(writing) / 2048, 8);
        // $1 mount point, $2 size in KiB, $3 where to keep what is left; then the command.
        const QString script = "mount -t tmpfs -o size=$2k tmpfs \"$1\" || exit 97\n"
                               "where=$1; keep=$3; shift 3\n"
                               "\"$@\"; status=$?\n"
                               "cp -a \"$where\"/. \"$keep\"/\n"
                               "exit $status\n";
        const QStringList arguments = QStringList{"--mount",
                                                  "sh",
                                                  "-c",
                                                  script,
                                                  "sh",
                                                  QString::fromStdString(written(writing)),
                                                  QString::number(kilobytes),
                                                  QString::fromStdString(kept),
                                                  cliPath()} +
                                      command(writing);
        QProcess process;
        process.start("unshare", arguments);
        if (!process.waitForStarted(10000) || !process.waitForFinished(300000))
            QSKIP("unshare is not available: covered by the preload library's cases");
        const QString err = QString::fromUtf8(process.readAllStandardError());
        if (process.exitCode() == 97 || err.startsWith("unshare:"))
            QSKIP(qPrintable("cannot mount a small file system here (" + err.trimmed() +
                             "): covered by the preload library's cases"));
        QVERIFY2(process.exitCode() == 4, qPrintable(err));
        QVERIFY_CONTAINS(err, "disk full");
        QVERIFY_CONTAINS(err, written(writing));
        fs::remove_all(written(writing));
        fs::rename(kept, written(writing));
        checkNothingLost(writing);
        checkRerunCompletes(writing);
    }

    //! The real thing where it can be made: a folder without write permission. Root writes
    //! there anyway, so as root the case is skipped, and the preload library's EACCES case
    //! above stands in for it.
    void aFolderWithoutWritePermissionIsNamed() {
        const Stage& bake = stageNamed("bake");
        prepare(bake);
        fs::permissions(caseDir_, fs::perms::owner_read | fs::perms::owner_exec);
        const bool enforced = ::access(caseDir_.c_str(), W_OK) != 0;
        if (!enforced) {
            fs::permissions(caseDir_, fs::perms::owner_all);
            QSKIP("permissions are not enforced for this user (root): covered by the preload "
                  "library's EACCES cases");
        }
        const CliResult result = runCli(command(bake));
        fs::permissions(caseDir_, fs::perms::owner_all);
        QCOMPARE_EXIT(result, 4);
        QVERIFY_CONTAINS(result.err, "permission denied");
        QVERIFY_CONTAINS(result.err, cache());
    }
};

AIRTRAP_TEST_GUILESS(TestDiskFaults)
#include "TestDiskFaults.moc"
