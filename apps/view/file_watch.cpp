#include "file_watch.hpp"

#include <rtlab/core/error.hpp>

#include <cerrno>
#include <cstring>

#include <fcntl.h>
#include <sys/inotify.h>
#include <unistd.h>

namespace rtlab::view {

namespace {
std::filesystem::path normal(const std::filesystem::path& p) { return std::filesystem::absolute(p).lexically_normal(); }
}  // namespace

FileWatch::FileWatch(std::chrono::milliseconds quiet) : m_quiet(quiet) {
    m_fd = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
    if (m_fd < 0) throw Error(std::string("live reload: inotify_init1 failed: ") + std::strerror(errno));
}

FileWatch::~FileWatch() {
    clear();
    if (m_fd >= 0) close(m_fd);
}

void FileWatch::clear() {
    for (const auto& [wd, folder] : m_folders) inotify_rm_watch(m_fd, wd);
    m_folders.clear();
    m_files.clear();
}

void FileWatch::watch(const std::vector<std::filesystem::path>& files) {
    clear();
    std::set<std::filesystem::path> folders;
    for (const auto& f : files) {
        const auto path = normal(f);
        m_files.insert(path.string());
        folders.insert(path.parent_path());
    }
    for (const auto& folder : folders) {
        const int wd = inotify_add_watch(m_fd, folder.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO);
        if (wd < 0) throw Error("live reload: cannot watch " + folder.string() + ": " + std::strerror(errno));
        m_folders.emplace_back(wd, folder);
    }
}

bool FileWatch::poll() {
    alignas(inotify_event) char buffer[8192];
    for (;;) {
        const ssize_t n = read(m_fd, buffer, sizeof buffer);
        if (n <= 0) break;
        for (ssize_t at = 0; at < n;) {
            const auto* event = reinterpret_cast<const inotify_event*>(buffer + at);
            at += static_cast<ssize_t>(sizeof(inotify_event) + event->len);
            if (event->len == 0) continue;
            for (const auto& [wd, folder] : m_folders) {
                if (wd != event->wd) continue;
                if (!(event->mask & (IN_CLOSE_WRITE | IN_MOVED_TO))) continue;
                if (m_files.count((folder / event->name).string())) {
                    m_pending = true;
                    m_last_event = std::chrono::steady_clock::now();
                }
            }
        }
    }
    if (m_pending && std::chrono::steady_clock::now() - m_last_event >= m_quiet) {
        m_pending = false;
        return true;
    }
    return false;
}

}  // namespace rtlab::view
