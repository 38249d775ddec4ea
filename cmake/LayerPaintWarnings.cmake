# SPDX-License-Identifier: GPL-3.0-or-later
# Compiler flags shared by every LayerPaint target: layerpaint_set_flags(target).
function(layerpaint_set_flags target)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
        -Wnon-virtual-dtor -Wcast-align -Woverloaded-virtual -Wno-missing-field-initializers)
    # Debug sections compressed (zlib) in objects, archives and binaries: about half the disk a
    # build with debug info takes; gdb and the sanitizers' symbolizers read them as they are.
    target_compile_options(${target} PRIVATE -gz)
    target_link_options(${target} PRIVATE -gz)
    # A source file of a unity build is not the main file, so GCC would warn about each class
    # there with a member of a type from that file's anonymous namespace.
    set(unity_gcc $<AND:$<CXX_COMPILER_ID:GNU>,$<BOOL:$<TARGET_PROPERTY:UNITY_BUILD>>>)
    target_compile_options(${target} PRIVATE $<${unity_gcc}:-Wno-subobject-linkage>)
    if(LAYERPAINT_STRICT)
        target_compile_options(${target} PRIVATE -Werror)
    endif()
    if(LAYERPAINT_SANITIZE)
        target_compile_options(${target} PRIVATE -fsanitize=address,undefined
            -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
        target_link_options(${target} PRIVATE -fsanitize=address,undefined)
        # GCC's may-be-uninitialized analysis gives false positives on instrumented code (in
        # libstdc++'s <regex> at -O1); the dev build keeps the warning.
        target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
    endif()
    if(LAYERPAINT_FUZZ)
        # Coverage for libFuzzer in every library; the fuzz targets link the fuzzer itself.
        target_compile_options(${target} PRIVATE -fsanitize=fuzzer-no-link)
    endif()
endfunction()
