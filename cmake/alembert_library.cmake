include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/alembert_warnings.cmake)

# alembert_add_library(<layer> SOURCES <files...> [DEPS <targets...>])
# Creates the static library alembert_<layer> (alias alembert::<layer>,
# exported as alembert::<layer>) and installs it into AlembertTargets.
function(alembert_add_library layer)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "" "SOURCES;DEPS")
  set(target alembert_${layer})
  add_library(${target} STATIC ${ARG_SOURCES})
  add_library(alembert::${layer} ALIAS ${target})
  set_target_properties(${target} PROPERTIES
    EXPORT_NAME ${layer}
    OUTPUT_NAME alembert_${layer}
    POSITION_INDEPENDENT_CODE ON)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_DEPS})
  alembert_set_warnings(${target})
  install(TARGETS ${target} EXPORT AlembertTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
endfunction()
