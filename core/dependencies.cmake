# What grass_core needs from Debian, found once for every build that compiles core: the main
# build (CMakeLists.txt) and the clang sanitizer build of the fuzz targets (tests/fuzz).
# Also turns on ccache where it is installed.
find_program(CCACHE_PROGRAM ccache)
if(CCACHE_PROGRAM)
    set(CMAKE_CXX_COMPILER_LAUNCHER ${CCACHE_PROGRAM})
    set(CMAKE_C_COMPILER_LAUNCHER ${CCACHE_PROGRAM})
endif()

find_package(glm REQUIRED)
find_package(OpenMesh REQUIRED)
find_package(TinyGLTF REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(Threads REQUIRED)
# Google Highway: the SIMD of the CPU physics (core/physics/physics_simd.h, issue 29).
find_package(hwy REQUIRED)
# Compressed glTF geometry (issue 26): KHR_draco_mesh_compression and EXT_meshopt_compression.
find_package(draco REQUIRED)
find_package(meshoptimizer REQUIRED)
# Debian's OpenImageIO CMake config demands the command-line tools package; pkg-config does not.
#   (find_package(OpenImageIO) fails on a machine without openimageio-tools.)
find_package(PkgConfig REQUIRED)
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)

