#include <rtlab/app/course_app.hpp>
#include <rtlab/app/progress_bar.hpp>
#include <rtlab/app/stop_on_interrupt.hpp>

#include "scene_fixtures.hpp"

#include <catch2/catch.hpp>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <string>
#include <thread>

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

using namespace rtlab;
using namespace rtlab::app;

TEST_CASE("the progress line shows tiles rate and time left", "[app]") {
    RenderProgress p{10, 40, {}, 5.0};
    p.rays.camera = 12'000'000;
    p.rays.shadow = 4'050'000;
    CHECK(format_progress(p, 8) == "[##......] 10/40 tiles  3.21 Mrays/s  0:05 elapsed  0:15 left");
    CHECK(format_progress(RenderProgress{0, 7, {}, 0.0}, 4) == "[....] 0/7 tiles  0 rays/s  0:00 elapsed  --:-- left");
    RenderProgress slow{1, 400, {}, 30.0};
    slow.rays.camera = 45'000;
    CHECK(format_progress(slow, 2) == "[..]   1/400 tiles  1.5 krays/s  0:30 elapsed  3:19:30 left");
    CHECK(format_progress(RenderProgress{40, 40, {}, 2.0}, 4).starts_with("[####] 40/40"));
}

TEST_CASE("the progress bar is silent when stderr is not a terminal or with quiet", "[app]") {
    std::FILE* file = std::tmpfile();
    REQUIRE(file);
    {
        ProgressBar bar(file, false);
        CHECK_FALSE(bar.enabled());
        for (int i = 1; i <= 5; ++i) bar.update(RenderProgress{i, 5, {}, 0.1 * i});
        bar.finish();
    }
    CHECK(std::ftell(file) == 0);
    std::fclose(file);

    // On a real terminal (a pseudo-terminal here) it draws, unless quiet.
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    REQUIRE(master >= 0);
    REQUIRE(::grantpt(master) == 0);
    REQUIRE(::unlockpt(master) == 0);
    std::FILE* tty = std::fopen(::ptsname(master), "w");
    REQUIRE(tty);
    {
        ProgressBar quiet(tty, true);
        CHECK_FALSE(quiet.enabled());
        quiet.update(RenderProgress{1, 2, {}, 1.0});
    }
    {
        ProgressBar bar(tty, false);
        CHECK(bar.enabled());
        bar.update(RenderProgress{1, 2, {}, 1.0});
        bar.update(RenderProgress{2, 2, {}, 2.0});
    }
    std::fclose(tty);
    // A pseudo-terminal hands its output over in pieces: read until it stays empty for a while.
    std::string drawn;
    for (;;) {
        pollfd ready{master, POLLIN, 0};
        if (::poll(&ready, 1, 500) <= 0) break;
        char buffer[512];
        const ssize_t n = ::read(master, buffer, sizeof buffer);
        if (n <= 0) break;
        drawn.append(buffer, static_cast<std::size_t>(n));
    }
    ::close(master);
    // Both updates (the last tile is always drawn), nothing from the quiet bar, and a final newline.
    CHECK(drawn.find("1/2 tiles") != std::string::npos);
    CHECK(drawn.find("2/2 tiles") != std::string::npos);
    CHECK(drawn.find("1/2 tiles") == drawn.rfind("1/2 tiles"));
    CHECK(drawn.ends_with("\r\n"));  // the terminal turns the newline into CR LF
}

TEST_CASE("Ctrl-C sets the stop flag instead of ending the process", "[app]") {
    struct sigaction before {};
    sigaction(SIGINT, nullptr, &before);
    {
        StopOnInterrupt stop;
        CHECK_FALSE(stop.interrupted());
        std::raise(SIGINT);
        CHECK(stop.interrupted());
        CHECK(stop.flag().load());
    }
    // The previous handler is back.
    struct sigaction after {};
    sigaction(SIGINT, nullptr, &after);
    CHECK(after.sa_handler == before.sa_handler);
    // A new one starts unset.
    StopOnInterrupt again;
    CHECK_FALSE(again.interrupted());
}

TEST_CASE("the course render summary gives the render's wall and processor seconds", "[app]") {
    // scripts/peer-povray.sh reads "in W s (C CPU s)" from this line; C is the processor time of the render
    // alone, all threads together.
    RenderJob job;
    job.scene = std::make_shared<Scene>(test::random_objects(60, 20, 7));
    job.camera = std::make_shared<PinholeCamera>(
        CameraSpec{.eye = {0, 2, 4}, .look_at = {0, 1, -10}, .vertical_fov_degrees = 50.0f, .width = 96, .height = 72});
    job.lights = {test::point_light(Point3(-4, 9, 6), 1.0f)};
    job.settings.pattern = PixelPattern::adaptive;
    job.settings.threads = 1;
    CourseOptions options;
    const std::filesystem::path out =
        std::filesystem::temp_directory_path() / ("rtlab_summary_test_" + std::to_string(::getpid()) + ".png");

    std::fflush(stdout);
    std::FILE* capture = std::tmpfile();
    REQUIRE(capture);
    const int saved = ::dup(STDOUT_FILENO);
    REQUIRE(::dup2(::fileno(capture), STDOUT_FILENO) >= 0);
    const CourseRenderResult result = run_course_render(job, options, out, "summary");
    std::fflush(stdout);
    ::dup2(saved, STDOUT_FILENO);
    ::close(saved);
    std::rewind(capture);
    char buffer[1024] = {};
    const std::size_t n = std::fread(buffer, 1, sizeof buffer - 1, capture);
    std::fclose(capture);
    std::filesystem::remove(out);
    const std::string line(buffer, n);

    std::smatch m;
    REQUIRE(std::regex_search(line, m, std::regex(R"(^summary: 96x72 in ([0-9.]+) s \(([0-9.]+) CPU s\), )")));
    CHECK(std::stod(m[1].str()) == Approx(result.stats.seconds).margin(0.005));
    CHECK(std::stod(m[2].str()) == Approx(result.cpu_seconds).margin(0.005));
    // Some it must spend (96x72 adaptive pixels over 80 objects), and no more than every core for as long as
    // the render lasted (clock ticks allowing; idle thread-pool workers of earlier tests may still spin).
    CHECK(result.cpu_seconds > 0.0);
    CHECK(result.cpu_seconds <= result.stats.seconds * std::thread::hardware_concurrency() + 0.02);
}
