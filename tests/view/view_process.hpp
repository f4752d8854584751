#pragma once
// Runs rtlab-view with commands on its standard input and reads the lines it prints, waiting for the ones a
// test needs ("pass 2", "saved FILE", "reloaded", "error: ...") instead of sleeping.
#include <chrono>
#include <string>
#include <vector>

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rtlab::test {

class ViewProcess {
public:
    explicit ViewProcess(const std::vector<std::string>& argv) {
        int in[2], out[2];
        if (pipe(in) != 0 || pipe(out) != 0) return;
        m_pid = fork();
        if (m_pid == 0) {
            dup2(in[0], 0);
            dup2(out[1], 1);
            close(in[1]);
            close(out[0]);
            std::vector<char*> args;
            for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
            args.push_back(nullptr);
            execv(args[0], args.data());
            _exit(127);
        }
        close(in[0]);
        close(out[1]);
        m_in = in[1];
        m_out = out[0];
    }
    ~ViewProcess() {
        if (m_pid > 0 && !m_exited) {
            kill(m_pid, SIGTERM);
            waitpid(m_pid, nullptr, 0);
        }
        if (m_in >= 0) close(m_in);
        if (m_out >= 0) close(m_out);
    }

    void send(const std::string& line) {
        const std::string text = line + "\n";
        if (write(m_in, text.data(), text.size()) < 0) m_failed = true;
    }

    /// Reads lines until one starts with `prefix` and returns it; "" when the process ended or two minutes passed
    /// (a guard against a hung viewer, not a timing).
    std::string wait_for(const std::string& prefix) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
        for (;;) {
            const auto nl = m_buffer.find('\n');
            if (nl != std::string::npos) {
                std::string line = m_buffer.substr(0, nl);
                m_buffer.erase(0, nl + 1);
                m_lines.push_back(line);
                if (line.rfind(prefix, 0) == 0) return line;
                continue;
            }
            const auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
            if (left.count() <= 0) return "";
            pollfd p{m_out, POLLIN, 0};
            if (poll(&p, 1, static_cast<int>(left.count())) <= 0) return "";
            char chunk[4096];
            const ssize_t n = read(m_out, chunk, sizeof chunk);
            if (n <= 0) return "";
            m_buffer.append(chunk, static_cast<std::size_t>(n));
        }
    }

    /// Waits for the exit; its status, or -1.
    int wait_exit() {
        int status = 0;
        if (waitpid(m_pid, &status, 0) != m_pid) return -1;
        m_exited = true;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    const std::vector<std::string>& lines() const { return m_lines; }

private:
    pid_t m_pid = -1;
    int m_in = -1, m_out = -1;
    bool m_exited = false, m_failed = false;
    std::string m_buffer;
    std::vector<std::string> m_lines;
};

}  // namespace rtlab::test
