#pragma once
// The folder every airtrap-cli test works in: a fresh temporary folder per test function, with the
// tiny scene (4 frames) written into it and a cache path beside it.
#include "cli/CliTestSupport.h"

#include <QTemporaryDir>
#include <memory>
#include <string>

namespace airtrap::clitest {

class CliFixture {
protected:
    std::unique_ptr<QTemporaryDir> temp_;
    std::string root_;
    std::string scene_; //!< tiny scene, 4 frames
    std::string cache_; //!< where most tests bake to

    //! For the test class's init(): a new folder with the tiny scene.
    void setUpFolder() {
        temp_ = std::make_unique<QTemporaryDir>();
        QVERIFY(temp_->isValid());
        root_ = temp_->path().toStdString();
        scene_ = writeScene("tiny.json", tinySceneText(4));
        cache_ = path("cache");
    }

    //! For the test class's cleanup().
    void tearDownFolder() { temp_.reset(); }

    std::string path(const std::string& name) const { return root_ + "/" + name; }

    std::string writeScene(const std::string& name, const std::string& text) const {
        writeText(path(name), text);
        return path(name);
    }

    //! Bakes the tiny scene into `dir` and checks that it worked.
    void bake(const std::string& dir, const QStringList& extra = {}) {
        const CliResult result = runCli(args({"bake", scene_, "--out", dir}) + extra);
        QCOMPARE_EXIT(result, 0);
    }
};

} // namespace airtrap::clitest
