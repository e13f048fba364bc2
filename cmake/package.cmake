# The installed C++ package (docs/library.md), from `cmake --install BUILD --prefix PREFIX`:
#   bin/frictionviz                                  the command line (also the imported frictionviz::frictionviz)
#   include/frictionviz/fv/*.hpp, fv/detail/         core's public headers (FV_CORE_PUBLIC_HEADERS below)
#   include/frictionviz/figures/figure_renderer.hpp  the figures layer's entry point
#   lib/libfvcore.a libfvfigdefs.a libfvrender.a libfvfigures.a
#   lib/cmake/frictionviz/                           find_package(frictionviz): frictionviz::core, ::figures
# The headers sit in include/frictionviz so that a consumer writes <fv/...> and <figures/...>, as the tree does,
# without fv/ and figures/ landing beside other projects' headers in the prefix. Nothing of tests/ or bench/ is
# installed, nor the app's own libraries (gui, anim, cli: the executable holds them). Room is left for other
# pieces (a Python module) under their own destinations.

set(FV_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/frictionviz)
set(FV_INCLUDE_DIR ${CMAKE_INSTALL_INCLUDEDIR}/frictionviz)

# The two targets a consumer links, named as in the tree (ALIAS) and installed (EXPORT_NAME):
#   frictionviz::core     the model, the solver and the numbers of every registered figure (fvcore with the
#                         figure definitions linked whole, so that the registry is complete); Eigen, threads
#   frictionviz::figures  core and the figures layer: pictures as PNG, SVG, PDF (render layer: GL through
#                         OSMesa at run time, cairo, Dear ImGui's text)
add_library(frictionviz_core INTERFACE)
target_link_libraries(frictionviz_core INTERFACE fvcore fvfigurelist)
set_target_properties(frictionviz_core PROPERTIES EXPORT_NAME core)
add_library(frictionviz::core ALIAS frictionviz_core)
add_library(frictionviz_figures INTERFACE)
target_link_libraries(frictionviz_figures INTERFACE frictionviz_core fvfigures)
set_target_properties(frictionviz_figures PROPERTIES EXPORT_NAME figures)
add_library(frictionviz::figures ALIAS frictionviz_figures)

# core's public headers: the API docs/library.md documents (its header table is checked against the installed
# set by the install_consumer test). The others in core/include/fv are the app's and the command line's
# (live simulation, share links, input files, number readers) and stay out. fv/detail/parallel_for.hpp is
# installed because sweep.hpp includes it; it is not part of the API.
set(FV_CORE_PUBLIC_HEADERS
  atomic_file.hpp
  figure_data.hpp
  figure_registry.hpp
  figures.hpp
  fit.hpp
  measurements.hpp
  paper_scheme.hpp
  param_ranges.hpp
  params.hpp
  rigid.hpp
  steady_state.hpp
  sweep.hpp
  units.hpp
  vec2.hpp
)
list(TRANSFORM FV_CORE_PUBLIC_HEADERS PREPEND ${PROJECT_SOURCE_DIR}/core/include/fv/)
install(FILES ${FV_CORE_PUBLIC_HEADERS} DESTINATION ${FV_INCLUDE_DIR}/fv)
install(FILES ${PROJECT_SOURCE_DIR}/core/include/fv/detail/parallel_for.hpp DESTINATION ${FV_INCLUDE_DIR}/fv/detail)
install(FILES ${PROJECT_SOURCE_DIR}/app/figures/figure_renderer.hpp DESTINATION ${FV_INCLUDE_DIR}/figures)

# Two export sets, so that a program that needs only the model does not need cairo, GLFW or ImGui to configure
# (find_package(frictionviz COMPONENTS core)).
install(TARGETS fvcore fvfigdefs fvfigurelist frictionviz_core frictionviz
        EXPORT frictionviz-core
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS fvrender fvfigures frictionviz_figures
        EXPORT frictionviz-figures
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT frictionviz-core NAMESPACE frictionviz:: DESTINATION ${FV_PACKAGE_DIR}
        FILE frictionviz-core-targets.cmake)
install(EXPORT frictionviz-figures NAMESPACE frictionviz:: DESTINATION ${FV_PACKAGE_DIR}
        FILE frictionviz-figures-targets.cmake)

include(CMakePackageConfigHelpers)
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/frictionviz-config.cmake.in
                              ${PROJECT_BINARY_DIR}/package/frictionviz-config.cmake
                              INSTALL_DESTINATION ${FV_PACKAGE_DIR})
# 0.x: a minor version may change the API, so find_package(frictionviz 0.1) accepts 0.1.* only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/frictionviz-config-version.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/package/frictionviz-config.cmake
              ${PROJECT_BINARY_DIR}/package/frictionviz-config-version.cmake
              ${PROJECT_SOURCE_DIR}/app/render/cmake/render_dependencies.cmake
        DESTINATION ${FV_PACKAGE_DIR})
