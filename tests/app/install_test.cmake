# SPDX-License-Identifier: GPL-3.0-or-later
# `cmake --install` into a fresh prefix puts the programs and the desktop integration where
# desktops look for them, the metadata validates, the installed `layerpaint-cli` finds its
# importer process under libexec, and the installed `layerpaint` answers --version and --help (in
# the preferred language) without a display.
# Run as: cmake -DBUILD_DIR=... -DPREFIX=... -DVERSION=... -DLIBEXECDIR=... [-DAPPSTREAMCLI=...]
#         [-DDESKTOP_FILE_VALIDATE=...] -P install_test.cmake
set(id io.github.layerpaint.LayerPaint)

function(fail)
    string(JOIN "" message ${ARGN})
    message(FATAL_ERROR "${message}")
endfunction()

file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
    fail("cmake --install failed: ${output}")
endif()

foreach(file bin/layerpaint bin/layerpaint-cli ${LIBEXECDIR}/layerpaint/layerpaint-import
        ${LIBEXECDIR}/layerpaint/layerpaint-image-codecs.so
        share/applications/${id}.desktop
        share/metainfo/${id}.metainfo.xml share/icons/hicolor/scalable/apps/${id}.svg)
    if(NOT EXISTS "${PREFIX}/${file}")
        fail("not installed: ${file}")
    endif()
endforeach()

# Files are parsed by the importer process, found relative to the installed program (not
# through LAYERPAINT_IMPORTER, which the tests set to the build tree's).
file(WRITE "${PREFIX}/triangle.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=LAYERPAINT_IMPORTER
    "${PREFIX}/bin/layerpaint-cli" info "${PREFIX}/triangle.obj"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT output MATCHES "\"triangles\": 1")
    fail("the installed layerpaint-cli cannot load a model (${result}): ${output}${error}")
endif()
# Images go through the image codecs module, found the same way.
execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=LAYERPAINT_IMAGE_CODECS
    "${PREFIX}/bin/layerpaint-cli" export builtin:trefoil --out "${PREFIX}/paint.png"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT EXISTS "${PREFIX}/paint.png")
    fail("the installed layerpaint-cli cannot write an image (${result}): ${output}${error}")
endif()

# The metainfo carries this version; the desktop entry starts the installed program.
file(READ "${PREFIX}/share/metainfo/${id}.metainfo.xml" metainfo)
if(NOT metainfo MATCHES "<release version=\"${VERSION}\" date=\"[0-9]+-[0-9]+-[0-9]+\"")
    fail("the metainfo has no release ${VERSION}")
endif()
file(READ "${PREFIX}/share/applications/${id}.desktop" desktop)
if(NOT desktop MATCHES "\nExec=layerpaint " OR NOT desktop MATCHES "\nIcon=${id}\n")
    fail("the desktop entry does not start layerpaint with the icon ${id}")
endif()
file(READ "${PREFIX}/share/icons/hicolor/scalable/apps/${id}.svg" icon)
if(NOT icon MATCHES "<svg [^>]*viewBox=\"0 0 128 128\"")
    fail("the icon is not the square SVG")
endif()

if(APPSTREAMCLI)
    execute_process(COMMAND "${APPSTREAMCLI}" validate --no-net
        "${PREFIX}/share/metainfo/${id}.metainfo.xml"
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL 0)
        fail("appstreamcli validate: ${output}")
    endif()
endif()
if(DESKTOP_FILE_VALIDATE)
    execute_process(COMMAND "${DESKTOP_FILE_VALIDATE}" "${PREFIX}/share/applications/${id}.desktop"
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL 0 OR NOT output STREQUAL "")
        fail("desktop-file-validate: ${output}")
    endif()
endif()

# Runs the installed layerpaint with arguments in a clean environment: no display, settings in
# a folder of the prefix, the language given; the output goes to out.
function(run_layerpaint out language settings_language)
    set(config "${PREFIX}/config")
    file(REMOVE_RECURSE "${config}")
    if(NOT settings_language STREQUAL "")
        file(WRITE "${config}/LayerPaint/LayerPaint.conf" "[ui]\nlanguage=${settings_language}\n")
    endif()
    execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
        --unset=LC_ALL --unset=LC_MESSAGES QT_QPA_PLATFORM=offscreen "XDG_CONFIG_HOME=${config}"
        "LANG=${language}" "LANGUAGE=" "${PREFIX}/bin/layerpaint" ${ARGN}
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
    if(NOT result EQUAL 0)
        fail("layerpaint ${ARGN} exited with ${result}: ${output}${error}")
    endif()
    set(${out} "${output}" PARENT_SCOPE)
endfunction()

run_layerpaint(version C "" --version)
if(NOT version STREQUAL "LayerPaint ${VERSION}\n")
    fail("layerpaint --version printed \"${version}\", not \"LayerPaint ${VERSION}\"")
endif()

run_layerpaint(help C "" --help)
foreach(expected "Layer-aware 3D painting of meshes." "--connectivity <engine>" "--version"
        "--help" "[file]")
    string(FIND "${help}" "${expected}" at)
    if(at EQUAL -1)
        fail("layerpaint --help does not say \"${expected}\":\n${help}")
    endif()
endforeach()

# The language follows the system, or the preference where one is set.
run_layerpaint(help de_DE.UTF-8 "" --help)
string(FIND "${help}" "Ebenenbewusstes 3D-Malen auf Netzen." at)
if(at EQUAL -1)
    fail("layerpaint --help is not German under LANG=de_DE.UTF-8:\n${help}")
endif()
run_layerpaint(help de_DE.UTF-8 zh_CN --help)
string(FIND "${help}" "对网格进行图层感知的三维绘画。" at)
if(at EQUAL -1)
    fail("layerpaint --help is not Chinese with ui/language=zh_CN:\n${help}")
endif()
run_layerpaint(help de_DE.UTF-8 en --help)
string(FIND "${help}" "Layer-aware 3D painting of meshes." at)
if(at EQUAL -1)
    fail("layerpaint --help is not English with ui/language=en:\n${help}")
endif()
