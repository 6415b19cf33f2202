# Instruments everything built after it with AddressSanitizer and UndefinedBehaviorSanitizer, and
# with the coverage counters that guide libFuzzer; the fuzz targets in test/fuzz add libFuzzer's
# main. The same build runs the C++ suite under the sanitizers (scripts/test_sanitizers.sh), so the
# core is compiled once for both. OpenCV itself stays Debian's uninstrumented gcc build, which links
# fine with clang objects.
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  message(FATAL_ERROR "TRIPOSE_BUILD_FUZZERS needs clang with libFuzzer "
                      "(e.g. -DCMAKE_CXX_COMPILER=clang++-14; Debian: clang-14 libclang-rt-14-dev)")
endif()
# Edge counters and their table only, not the comparison hooks of -fsanitize=fuzzer-no-link
# (trace-cmp): a hook call on every comparison made the C++ suite under the sanitizers run several
# times slower, and the library's branches are mostly on floating-point values, which those hooks do
# not trace. The fuzz targets' own code (the input decoder, the problem reader) is compiled with
# -fsanitize=fuzzer, hooks included.
add_compile_options(-fsanitize=address,undefined -fsanitize-coverage=inline-8bit-counters,pc-table
                    -fno-sanitize-recover=undefined -fno-omit-frame-pointer -gline-tables-only)
add_link_options(-fsanitize=address,undefined)
