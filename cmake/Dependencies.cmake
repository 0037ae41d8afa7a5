# Every dependency is a Debian 12 package installed by scripts/setup; nothing is downloaded here.
find_package(Threads REQUIRED)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(assimp REQUIRED)
find_package(ZLIB REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(CBC REQUIRED IMPORTED_TARGET cbc)
# Geodesy for waypoint exports (libgeographiclib-dev ships its Find module here).
list(APPEND CMAKE_MODULE_PATH /usr/share/cmake/geographiclib)
find_package(GeographicLib REQUIRED)
# Flight files: DJI's KMZ is a zip (libzip-dev), KML and WPML are XML (libpugixml-dev).
# (through pkg-config: Debian's libzip CMake config also demands the zipcmp tools)
pkg_check_modules(LIBZIP REQUIRED IMPORTED_TARGET libzip)
find_package(pugixml REQUIRED)
if(HULLINSPECT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(HULLINSPECT_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
# The Python module (python/): pybind11-dev and python3-dev for Debian's /usr/bin/python3. Not in
# sanitizer builds: an ASan-instrumented extension cannot be loaded into the uninstrumented python3
# without preloading the ASan runtime, which then reports CPython's own allocations.
option(HULLINSPECT_BUILD_PYTHON "Build the hullinspect Python module" ON)
if(HULLINSPECT_BUILD_PYTHON AND NOT HULLINSPECT_SANITIZE)
  set(Python3_EXECUTABLE /usr/bin/python3)
  # Development.Embed: tests/python_planners runs Python planners inside a C++ test program.
  find_package(Python3 REQUIRED COMPONENTS Interpreter Development.Module Development.Embed)
  set(PYBIND11_FINDPYTHON ON)
  find_package(pybind11 CONFIG REQUIRED)
  set(HULLINSPECT_WITH_PYTHON ON)
endif()
