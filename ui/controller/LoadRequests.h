#pragma once
// The frame loader's mailbox: what the GUI asked for since the loader thread last looked.
// Requests merge instead of queueing: a newer frame replaces an older one still waiting, so
// dragging the timeline over a hundred frames costs a load or two, not a hundred.
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>

namespace airtrap {

//! Work taken from LoadRequests in one go, to be done in the order of the fields.
struct LoadWork {
    //! A cache folder to switch to ("" = none), with the generation that tags its results.
    std::optional<std::string> directory;
    int generation = 0;
    //! Re-read the manifest of the current folder.
    bool refresh = false;
    //! The newest frame asked for.
    std::optional<int> frame;
    //! End the loader thread.
    bool quit = false;

    //! True when there is nothing to do.
    bool empty() const { return !directory && !refresh && !frame && !quit; }
};

class LoadRequests {
public:
    //! Switches to `directory`; a frame still waiting belonged to the old folder and is dropped.
    void setDirectory(const std::string& directory, int generation);
    //! Asks to re-read the manifest.
    void refresh();
    //! Asks for `frame`, replacing a frame still waiting.
    void load(int frame);
    //! Withdraws the waiting frame (the GUI found it in memory).
    void cancelLoad();
    //! Asks the loader thread to end.
    void quit();

    //! Blocks until there is work, then hands all of it over and starts afresh.
    LoadWork take();

private:
    //! Applies `change` to the pending work and wakes the loader thread.
    template <typename Change>
    void update(Change&& change);

    std::mutex mutex_;
    std::condition_variable arrived_;
    LoadWork pending_;
};

} // namespace airtrap
