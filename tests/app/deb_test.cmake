# SPDX-License-Identifier: GPL-3.0-or-later
# `cpack -G DEB` from the build folder makes layerpaint_<version>_<arch>.deb; its control fields
# and files are what Debian expects; unpacked with `dpkg-deb -x` into a temporary root, the
# programs run from there (the importer found beside them under libexec, the translations
# embedded); `apt-get install --simulate` resolves every Depends on this system; lintian (when
# LINTIAN is given) reports no error. Nothing is installed for real.
# Skips (prints SKIPPED) only where dpkg-deb or apt-get do not exist, i.e. not on Debian.
# Run as: cmake -DBUILD_DIR=... -DWORK=... -DVERSION=... [-DLINTIAN=...] -P deb_test.cmake
set(id io.github.layerpaint.LayerPaint)

function(fail)
    string(JOIN "" message ${ARGN})
    message(FATAL_ERROR "${message}")
endfunction()

find_program(DPKG_DEB dpkg-deb)
find_program(DPKG dpkg)
find_program(APT_GET apt-get)
if(NOT DPKG_DEB OR NOT DPKG OR NOT APT_GET)
    message("SKIPPED: dpkg-deb, dpkg or apt-get is missing (not a Debian system)")
    return()
endif()
find_program(DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT DPKG_SHLIBDEPS)
    fail("dpkg-shlibdeps is missing: install dpkg-dev (scripts/install-deps.sh --test)")
endif()

# The package, from the install rules of this build (cpack builds nothing new: the tree is built).
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CMAKE_CPACK_COMMAND}" -G DEB --config "${BUILD_DIR}/CPackConfig.cmake"
    -B "${WORK}" WORKING_DIRECTORY "${BUILD_DIR}"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
    fail("cpack -G DEB failed (${result}): ${output}")
endif()
execute_process(COMMAND "${DPKG}" --print-architecture OUTPUT_VARIABLE arch
    OUTPUT_STRIP_TRAILING_WHITESPACE)
set(deb "${WORK}/layerpaint_${VERSION}_${arch}.deb")
if(NOT EXISTS "${deb}")
    file(GLOB made "${WORK}/*.deb")
    fail("cpack made no ${deb} (made: ${made})")
endif()

# Control fields.
function(field out name)
    execute_process(COMMAND "${DPKG_DEB}" --field "${deb}" ${name} OUTPUT_VARIABLE value
        RESULT_VARIABLE result OUTPUT_STRIP_TRAILING_WHITESPACE)
    if(NOT result EQUAL 0)
        fail("dpkg-deb --field ${deb} ${name} failed")
    endif()
    set(${out} "${value}" PARENT_SCOPE)
endfunction()
field(package Package)
field(version Version)
field(section Section)
field(maintainer Maintainer)
field(description Description)
field(depends Depends)
if(NOT package STREQUAL "layerpaint" OR NOT version STREQUAL "${VERSION}"
        OR NOT section STREQUAL "graphics")
    fail("control: Package ${package}, Version ${version}, Section ${section}; expected "
        "layerpaint, ${VERSION}, graphics")
endif()
if(NOT maintainer MATCHES "^[^<]+ <[^@>]+@[^>]+>$")
    fail("control: Maintainer \"${maintainer}\" is not \"Name <address>\"")
endif()
if(NOT description MATCHES "^[^\n]+\n .+")
    fail("control: Description has no synopsis and long description:\n${description}")
endif()
# dpkg-shlibdeps filled in the libraries; what is loaded at run time is named by hand.
foreach(dependency libc6 "libstdc\\+\\+6" libqt6widgets6 libqt6openglwidgets6 libepoxy0
        "libassimp[0-9]+" "libopenimageio[0-9.]+" libegl1 libgl1 qt6-qpa-plugins)
    if(NOT depends MATCHES "(^|, )${dependency}( |,|$)")
        fail("control: Depends lacks ${dependency}: ${depends}")
    endif()
endforeach()

# Files, under /usr.
execute_process(COMMAND "${DPKG_DEB}" --contents "${deb}" OUTPUT_VARIABLE contents)
foreach(file bin/layerpaint bin/layerpaint-cli libexec/layerpaint/layerpaint-import
        libexec/layerpaint/layerpaint-image-codecs.so
        share/applications/${id}.desktop share/metainfo/${id}.metainfo.xml
        share/icons/hicolor/scalable/apps/${id}.svg share/doc/layerpaint/copyright
        share/doc/layerpaint/changelog.gz share/man/man1/layerpaint.1.gz
        share/man/man1/layerpaint-cli.1.gz)
    if(NOT contents MATCHES " \\./usr/${file}\n")
        fail("not in the package: /usr/${file}\n${contents}")
    endif()
endforeach()
string(REPLACE "\n" ";" entries "${contents}")
foreach(entry IN LISTS entries)
    if(NOT entry STREQUAL "" AND NOT entry MATCHES "^[-d]rw[-x]r-[-x]r-[-x] root/root .* \\./usr/"
            AND NOT entry MATCHES " \\./$")
        fail("not a root-owned, world-readable file under /usr: ${entry}")
    endif()
endforeach()

# Unpacked into a temporary root: the programs run from there.
set(root "${WORK}/root")
execute_process(COMMAND "${DPKG_DEB}" -x "${deb}" "${root}" RESULT_VARIABLE result
    ERROR_VARIABLE error)
if(NOT result EQUAL 0)
    fail("dpkg-deb -x failed: ${error}")
endif()
execute_process(COMMAND gzip -dc "${root}/usr/share/doc/layerpaint/changelog.gz"
    OUTPUT_VARIABLE changelog)
if(NOT changelog MATCHES "^layerpaint \\(${VERSION}\\) ")
    fail("the changelog's latest entry is not ${VERSION} (add one to data/debian/changelog)")
endif()

# Runs a program of the unpacked root in a clean environment: no display, no importer or image
# codecs from the build tree, settings in the work folder; the output goes to out.
function(run out language program)
    execute_process(COMMAND "${CMAKE_COMMAND}" -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY
        --unset=LAYERPAINT_IMPORTER --unset=LAYERPAINT_IMAGE_CODECS --unset=LC_ALL --unset=LC_MESSAGES QT_QPA_PLATFORM=offscreen
        "XDG_CONFIG_HOME=${WORK}/config" "LANG=${language}" "LANGUAGE="
        "${root}/usr/bin/${program}" ${ARGN}
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
    if(NOT result EQUAL 0)
        fail("the packaged ${program} ${ARGN} exited with ${result}: ${output}${error}")
    endif()
    set(${out} "${output}" PARENT_SCOPE)
endfunction()

run(output C layerpaint --version)
if(NOT output STREQUAL "LayerPaint ${VERSION}\n")
    fail("the packaged layerpaint --version printed \"${output}\"")
endif()
run(output de_DE.UTF-8 layerpaint --help)
string(FIND "${output}" "Ebenenbewusstes 3D-Malen auf Netzen." at)
if(at EQUAL -1)
    fail("the packaged layerpaint --help is not German under LANG=de_DE.UTF-8:\n${output}")
endif()
run(output C layerpaint-cli info builtin:trefoil)
if(NOT output MATCHES "\"triangles\": [1-9][0-9]*")
    fail("the packaged layerpaint-cli info builtin:trefoil printed: ${output}")
endif()
# A file goes through the importer process, found relative to the program.
file(WRITE "${WORK}/triangle.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
run(output C layerpaint-cli info "${WORK}/triangle.obj")
if(NOT output MATCHES "\"triangles\": 1")
    fail("the packaged layerpaint-cli cannot load a model: ${output}")
endif()
# Images go through the image codecs module, found the same way.
run(output C layerpaint-cli export builtin:trefoil --out "${WORK}/paint.png")
if(NOT EXISTS "${WORK}/paint.png")
    fail("the packaged layerpaint-cli cannot write an image: ${output}")
endif()

# Every Depends resolves on this system (a simulation: nothing is installed).
execute_process(COMMAND "${CMAKE_COMMAND}" -E env LC_ALL=C "${APT_GET}" install --simulate
    --no-install-recommends "${deb}"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
if(NOT result EQUAL 0 OR NOT output MATCHES "\nInst layerpaint ")
    fail("apt-get install --simulate ${deb} does not resolve (${result}):\n${output}${error}")
endif()

if(LINTIAN)
    execute_process(COMMAND "${LINTIAN}" --fail-on error "${deb}"
        RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE error)
    if(NOT result EQUAL 0)
        fail("lintian reports errors on ${deb} (${result}):\n${output}${error}")
    endif()
    message("lintian:\n${output}")
endif()
