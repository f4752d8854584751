#pragma once
// Live reload: inotify on the folders of the scene file and of the files it names. Editors save by writing in
// place (close-write) or by writing a temporary file and renaming it over the old one (moved-to); both count.
// Changes are debounced: poll() reports a change once no event came for the quiet period.
#include <chrono>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace rtlab::view {

class FileWatch {
public:
    explicit FileWatch(std::chrono::milliseconds quiet = std::chrono::milliseconds(100));
    ~FileWatch();
    FileWatch(const FileWatch&) = delete;
    FileWatch& operator=(const FileWatch&) = delete;

    /// Watches exactly these files (replacing the previous set): their folders are watched and events for
    /// other names in them are ignored. Throws rtlab::Error when inotify cannot be set up.
    void watch(const std::vector<std::filesystem::path>& files);
    /// Reads pending events without blocking; true once when a watched file changed and the quiet period has
    /// passed since its last event.
    bool poll();

private:
    void clear();

    int m_fd = -1;
    std::chrono::milliseconds m_quiet;
    std::vector<int> m_watches;
    std::set<std::string> m_files;  // absolute, lexically normal paths
    std::vector<std::pair<int, std::filesystem::path>> m_folders;
    bool m_pending = false;
    std::chrono::steady_clock::time_point m_last_event;
};

}  // namespace rtlab::view
