# The web viewer (viewer/) and what `maquette view` needs.
#
# - cpp-httplib (Debian libcpp-httplib-dev, through pkg-config) for the server of `maquette view`,
#   the plug-in libmaquette_view.so (framework/plugins).
# - When npm is available, the target maquette_viewer (part of ALL) runs `npm ci` on a copy of
#   viewer/package.json + package-lock.json in the build tree (the source tree stays clean) and
#   bundles the viewer with esbuild into ${MAQUETTE_VIEWER_DIR} = build/share/maquette/viewer,
#   where `maquette view` finds it next to bin/. Without npm the viewer is skipped with a message.
find_package(PkgConfig REQUIRED)
pkg_check_modules(HTTPLIB REQUIRED IMPORTED_TARGET cpp-httplib)

set(MAQUETTE_VIEWER_DIR ${PROJECT_BINARY_DIR}/share/maquette/viewer)
find_program(MAQUETTE_NPM npm)
find_program(MAQUETTE_NODE NAMES node nodejs)

if(NOT MAQUETTE_NPM OR NOT MAQUETTE_NODE)
  message(STATUS "npm or node not found: the web viewer (viewer/) is not built and `maquette view` "
                 "has no page to serve; install npm (Debian package npm) and re-run cmake")
  return()
endif()

set(_viewer_src ${PROJECT_SOURCE_DIR}/viewer)
set(_viewer_work ${PROJECT_BINARY_DIR}/viewer-npm)
file(GLOB _viewer_sources CONFIGURE_DEPENDS ${_viewer_src}/src/*)

# npm ci --prefer-offline: uses the npm cache when it has the packages, the registry otherwise.
add_custom_command(
  OUTPUT ${_viewer_work}/node_modules/.maquette-stamp
  COMMAND ${CMAKE_COMMAND} -E make_directory ${_viewer_work}
  COMMAND ${CMAKE_COMMAND} -E copy ${_viewer_src}/package.json ${_viewer_src}/package-lock.json
          ${_viewer_work}/
  COMMAND ${MAQUETTE_NPM} ci --no-audit --no-fund --prefer-offline --loglevel=error
  COMMAND ${CMAKE_COMMAND} -E touch ${_viewer_work}/node_modules/.maquette-stamp
  DEPENDS ${_viewer_src}/package.json ${_viewer_src}/package-lock.json
  WORKING_DIRECTORY ${_viewer_work}
  COMMENT "viewer: npm ci"
  VERBATIM)
add_custom_command(
  OUTPUT ${MAQUETTE_VIEWER_DIR}/app.js ${MAQUETTE_VIEWER_DIR}/index.html
  COMMAND ${CMAKE_COMMAND} -E copy_directory ${_viewer_src}/src ${_viewer_work}/src
  COMMAND ${CMAKE_COMMAND} -E copy ${_viewer_src}/build.mjs ${_viewer_work}/build.mjs
  COMMAND ${MAQUETTE_NODE} ${_viewer_work}/build.mjs ${MAQUETTE_VIEWER_DIR}
  DEPENDS ${_viewer_work}/node_modules/.maquette-stamp ${_viewer_src}/build.mjs ${_viewer_sources}
  WORKING_DIRECTORY ${_viewer_work}
  COMMENT "viewer: esbuild bundle into ${MAQUETTE_VIEWER_DIR}"
  VERBATIM)
add_custom_target(maquette_viewer ALL DEPENDS ${MAQUETTE_VIEWER_DIR}/app.js)
install(DIRECTORY ${MAQUETTE_VIEWER_DIR}/ DESTINATION share/maquette/viewer OPTIONAL)
