# Warnings for our own targets, the sanitizer build (applied globally so every object,
# including tests, is instrumented) and code generation.
function(ramus_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                            -Wno-sign-conversion -Werror=return-type)
endfunction()

# UBSan's vptr check (dynamic types behind casts and member calls) is left out: ramus has no
# virtual functions, so it only instrumented the libraries' headers, for about a tenth of the
# sanitized build's compile time (skeleton's largest unity file 42 → 38 s, 2026-12-05).
if(RAMUS_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize=vptr -fno-omit-frame-pointer
                      -fno-sanitize-recover=undefined)
  add_link_options(-fsanitize=address,undefined)
endif()
if(RAMUS_BUILD_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# Copies and fills of a bounded but unknown size (a float's text from the writer's cache, a
# name into a JSON buffer) go to the C library instead of inline `rep movsq`/`rep stosq`, whose
# start-up of tens of cycles made them the hot spots of the GLB writer under perf on Intel cores
# (docs/BENCHMARKS.md, session 8). GCC on x86 only; other compilers keep their defaults.
include(CheckCXXCompilerFlag)
check_cxx_compiler_flag(-mstringop-strategy=libcall RAMUS_HAS_STRINGOP_LIBCALL)
if(RAMUS_HAS_STRINGOP_LIBCALL)
  add_compile_options(-mstringop-strategy=libcall)
endif()
