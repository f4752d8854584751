# Every dependency is a Debian 12 package (scripts/setup.sh installs them); nothing is downloaded.
find_package(glm REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(fmt REQUIRED)
find_package(Threads REQUIRED)
# zlib (zlib1g-dev) compresses core's PNG output: stb_image_write's own deflate was 7x slower.
find_package(ZLIB REQUIRED)
# OpenEXR 3 (libopenexr-dev) for render's .exr output: float RGB channels.
find_package(OpenEXR 3 REQUIRED)

# Header-only packages without a CMake config: stb (we compile its implementation ourselves in core) and
# pcg-cpp. Both live in /usr/include on Debian.
find_path(STB_INCLUDE_DIR stb_image.h PATH_SUFFIXES stb REQUIRED)
find_path(PCG_INCLUDE_DIR pcg_random.hpp REQUIRED)

if(RTLAB_BUILD_APPS)
  find_package(CLI11 REQUIRED)
endif()
if(RTLAB_BUILD_TESTS)
  find_package(Catch2 2 REQUIRED)
endif()
if(RTLAB_BUILD_BENCH OR RTLAB_BUILD_APPS)
  find_package(benchmark QUIET)
  if(NOT benchmark_FOUND)
    message(STATUS "rtlab: Google Benchmark not found; micro-benchmarks are not built")
  endif()
endif()

set(RTLAB_HAVE_EMBREE OFF)
if(RTLAB_WITH_EMBREE)
  find_package(embree 3 QUIET)
  if(embree_FOUND)
    set(RTLAB_HAVE_EMBREE ON)
    message(STATUS "rtlab: Embree ${embree_VERSION} found; the 'embree' reference backend is built")
  else()
    message(STATUS "rtlab: Embree 3 not found (apt-get install libembree-dev); the 'embree' backend is not built")
  endif()
endif()
