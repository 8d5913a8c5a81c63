# Dependencies come from Debian -dev packages (installed by `make deps`), never downloaded.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(CLI11 2.1 REQUIRED)
# fmt: only its Dragonbox float-to-decimal core, header-only (src/core/float_text.cpp).
find_package(fmt 9 REQUIRED)
# CGAL (Debian libcgal-dev, header-only, with GMP/MPFR): its Polygon Mesh Processing
# autorefinement resolves the intersections for the solid union (src/mesh/solid_union.cpp).
# Licence: CGAL's Polygon Mesh Processing is GPL-3.0-or-later (docs/welded.md, "Solid union");
# -DRAMUS_WITH_CGAL=OFF builds ramus without it (and without the solid union).
if(RAMUS_WITH_CGAL)
  set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
  find_package(CGAL 5.5 REQUIRED)
endif()
if(RAMUS_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(RAMUS_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()

# cpp-httplib (the studio server): Debian builds it as a library; its pkg-config flags select
# the same TLS/compression options the library was built with.
find_package(PkgConfig REQUIRED)
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)
find_package(Threads REQUIRED)

# jemalloc (Debian libjemalloc-dev) for the ramus tool and the benchmarks: a batch of box
# skeletons makes ~900 small allocations per skeleton (one Mesh per bone), where glibc's
# malloc/free took 11 % of the time and jemalloc ~20 % less wall time overall (docs/BENCHMARKS.md).
# The library itself uses whatever allocator the program that links it has.
if(RAMUS_USE_JEMALLOC)
  pkg_check_modules(JEMALLOC REQUIRED IMPORTED_TARGET jemalloc)
endif()

# stb (header-only, Debian libstb-dev puts headers in /usr/include/stb)
find_path(STB_INCLUDE_DIR stb_image_write.h PATH_SUFFIXES stb REQUIRED)
add_library(ramus_stb INTERFACE)
target_include_directories(ramus_stb SYSTEM INTERFACE ${STB_INCLUDE_DIR})
add_library(ramus::stb ALIAS ramus_stb)

# tinygltf (header-only in Debian's libtinygltf-dev), used to read glTF files back
find_path(TINYGLTF_INCLUDE_DIR tiny_gltf.h REQUIRED)
add_library(ramus_tinygltf INTERFACE)
target_include_directories(ramus_tinygltf SYSTEM INTERFACE ${TINYGLTF_INCLUDE_DIR})
target_link_libraries(ramus_tinygltf INTERFACE nlohmann_json::nlohmann_json)
add_library(ramus::tinygltf ALIAS ramus_tinygltf)
