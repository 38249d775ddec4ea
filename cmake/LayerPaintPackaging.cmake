# SPDX-License-Identifier: GPL-3.0-or-later
# The Debian package (`cpack -G DEB` in the build folder): the installed programs and desktop
# integration, plus what Debian policy asks of a package: the copyright file, the changelog and
# the manual pages, compressed with `gzip -9n` (no timestamp, so the package is reproducible).
# Depends is computed from the programs' shared libraries by dpkg-shlibdeps (dpkg-dev).

set(LAYERPAINT_DEB_MAINTAINER "The LayerPaint developers <layerpaint@users.noreply.github.com>"
    CACHE STRING "The Maintainer field of the Debian package")

# Compressed copies in the build folder, remade when the source changes (at configure time:
# gzip is part of every Debian system, and the files are tiny).
find_program(LAYERPAINT_GZIP gzip REQUIRED)
function(layerpaint_gzip source output)
    execute_process(COMMAND "${LAYERPAINT_GZIP}" -9 -n -c "${source}" OUTPUT_FILE "${output}"
        RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "gzip ${source} failed (${result})")
    endif()
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${source}")
endfunction()

set(packaging_dir ${PROJECT_BINARY_DIR}/packaging)
file(MAKE_DIRECTORY ${packaging_dir})
set(doc_dir ${CMAKE_INSTALL_DATADIR}/doc/layerpaint)
layerpaint_gzip(${PROJECT_SOURCE_DIR}/data/debian/changelog ${packaging_dir}/changelog.gz)
install(FILES ${PROJECT_SOURCE_DIR}/data/debian/copyright ${packaging_dir}/changelog.gz
    DESTINATION ${doc_dir})
set(man_pages layerpaint-cli)
if(LAYERPAINT_BUILD_GUI)
    list(APPEND man_pages layerpaint)
endif()
foreach(page IN LISTS man_pages)
    layerpaint_gzip(${PROJECT_SOURCE_DIR}/data/man/${page}.1 ${packaging_dir}/${page}.1.gz)
    install(FILES ${packaging_dir}/${page}.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endforeach()
# Folders rwxr-xr-x whatever the umask of the one packaging.
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ
    GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME layerpaint)
set(CPACK_PACKAGE_VENDOR "The LayerPaint developers")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "3D painter for surfaces hidden behind others")
# Lines under 80 characters and an empty line between paragraphs, as dpkg shows them.
set(CPACK_PACKAGE_DESCRIPTION [[
LayerPaint is a 3D painter for the surfaces that other surfaces hide: the
inside of a cup, the far side of a knotted tube, the second of four horses in
a row. Open a model (glTF, OBJ, PLY, STL, OFF), orbit, paint into its textures
or vertex colours, undo and save.

With layer-aware painting on, the view is split into depth layers and
regions, so one stroke can follow a surface behind whatever occludes it. A
command-line tool, layerpaint-cli, paints from scripts without a display.]])
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${LAYERPAINT_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Opened at run time, so dpkg-shlibdeps cannot see them: libepoxy loads libEGL (the headless
# context) and libGL; without Qt's platform plugins the window cannot open; the SVG plugin draws
# the window icon and Qt's translations its own dialogs.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libgl1")
if(LAYERPAINT_BUILD_GUI)
    string(APPEND CPACK_DEBIAN_PACKAGE_DEPENDS ", qt6-qpa-plugins")
    set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libqt6svg6, qt6-translations-l10n")
endif()
include(CPack)
