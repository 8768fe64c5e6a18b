# Box2D v3 for pivot-bench, built from the source tree PIVOT_BOX2D_V3_SOURCE names (Debian does
# not package it; README, "Benchmark"). Its own CMake is not used: its box2d::box2d target would
# clash with Debian's Box2D 2.4.1, which the bench links too. Its C files are compiled here as
# its Release build compiles them (C17 with GNU extensions, -O3 from the Release flags,
# NDEBUG), with AVX2 unless PIVOT_BOX2D_V3_AVX2 is off, and with hidden visibility: the two
# versions define a few global variables of the same name (b2_toiCalls, ...), which must not
# pre-empt Box2D 2.4.1's own from the executable.
find_package(Threads REQUIRED)
set(v3 "${PIVOT_BOX2D_V3_SOURCE}")
if(NOT EXISTS "${v3}/include/box2d/box2d.h" OR NOT EXISTS "${v3}/src/solver.c")
    message(FATAL_ERROR "PIVOT_BOX2D_V3_SOURCE=${v3} is not a Box2D v3 source tree (no "
                        "include/box2d/box2d.h and src/solver.c in it)")
endif()
file(GLOB box2d_v3_sources CONFIGURE_DEPENDS "${v3}/src/*.c")
enable_language(C)
add_library(pivot_box2d_v3 STATIC ${box2d_v3_sources})
set_target_properties(pivot_box2d_v3 PROPERTIES
    C_STANDARD 17
    C_EXTENSIONS ON
    C_VISIBILITY_PRESET hidden
    POSITION_INDEPENDENT_CODE ON)
target_include_directories(pivot_box2d_v3 PUBLIC "${v3}/include" PRIVATE "${v3}/src")
target_compile_definitions(pivot_box2d_v3 PRIVATE $<$<NOT:$<CONFIG:Debug>>:NDEBUG>)
if(PIVOT_BOX2D_V3_AVX2)
    target_compile_definitions(pivot_box2d_v3 PRIVATE BOX2D_AVX2)
    target_compile_options(pivot_box2d_v3 PRIVATE -mavx2 -mfma)
endif()
target_link_libraries(pivot_box2d_v3 PUBLIC m)

# The bench's Box2D v3 engine: the one translation unit that includes v3's headers (their
# box2d/box2d.h has the same name as Box2D 2.4.1's). The task pool it steps on is pivot-bench's
# own (bench/engines/task_pool.cpp), built with or without v3: pivot2d's worlds can use it too.
add_library(pivot_bench_box2d_v3 STATIC
    ${PROJECT_SOURCE_DIR}/testbed/bench/engines/box2d_v3_engine.cpp)
pivot_target_defaults(pivot_bench_box2d_v3)
target_include_directories(pivot_bench_box2d_v3 PRIVATE ${PROJECT_SOURCE_DIR}/testbed)
target_link_libraries(pivot_bench_box2d_v3 PRIVATE pivot::pivot pivot_box2d_v3 Threads::Threads)
