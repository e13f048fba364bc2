# Render memory is flat in the number of figures (docs/reliability.md, Memory): 1 figure against 40 in one call, peak RSS.
add_executable(fv_render_memory_test ${CMAKE_CURRENT_LIST_DIR}/render_memory_test.cpp)
target_include_directories(fv_render_memory_test PRIVATE ${PROJECT_SOURCE_DIR}/tests/tools)
target_link_libraries(fv_render_memory_test PRIVATE fv_warnings)
if(FV_SANITIZE)
  target_compile_definitions(fv_render_memory_test PRIVATE FV_SANITIZED=1)
endif()
add_dependencies(fv_render_memory_test frictionviz)
add_test(NAME render_memory_flat
         COMMAND fv_render_memory_test $<TARGET_FILE:frictionviz> ${CMAKE_CURRENT_BINARY_DIR}/render-memory)
set_tests_properties(render_memory_flat PROPERTIES LABELS reliability TIMEOUT 300)
