include_guard(GLOBAL)
include(GoogleTest)
include(${CMAKE_CURRENT_LIST_DIR}/alembert_warnings.cmake)

# alembert_add_test(<name> SOURCES <files...> [LIBS <targets...>] [LABELS <labels...>]
#                   [LARGE <gtest filter>] [SHARD_WEIGHT <w>])
# Builds test_<name> against GTest::gtest_main, LIBS and alembert_test_support,
# and registers its test cases with CTest. LABELS defaults to the name of the
# current source directory (sym, vec, mech, ...). The test cases LARGE matches (a
# --gtest_filter pattern, e.g. "WhippleBicycle.*:BicycleScript.*") get the label `large`
# instead: models that take seconds here and minutes under the sanitizers, whose code paths
# smaller models of the same kind cover (the sanitizer pass of scripts/test.sh leaves them out).
# With ALEMBERT_TEST_SHARDS = N > 0 the program is registered as N tests <name>.shard<i>, each
# running every N-th of its cases but LARGE's in one process (GoogleTest's sharding), and
# <name>.large running LARGE's cases: a failure names its case in the test's output.
# SHARD_WEIGHT w (default 1) gives a program whose cases take longer w times as many shards,
# and every shard the COST w, so CTest starts the heaviest first (a clean clone has no
# timings of earlier runs to order by): the equations' program ran two 195 s shards under the
# sanitizers while most took under a minute.
function(alembert_add_test name)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "LARGE;SHARD_WEIGHT" "SOURCES;LIBS;LABELS")
  if(NOT ARG_SHARD_WEIGHT)
    set(ARG_SHARD_WEIGHT 1)
  endif()
  if(NOT ARG_LABELS)
    get_filename_component(ARG_LABELS ${CMAKE_CURRENT_SOURCE_DIR} NAME)
  endif()
  set(target test_${name})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE GTest::gtest_main ${ARG_LIBS} alembert_test_support)
  alembert_set_warnings(${target})
  if(ALEMBERT_TEST_PROGRAM_FLAGS)
    separate_arguments(_alembert_test_flags UNIX_COMMAND "${ALEMBERT_TEST_PROGRAM_FLAGS}")
    target_compile_options(${target} PRIVATE ${_alembert_test_flags})
  endif()
  if(ALEMBERT_TEST_SHARDS GREATER 0)
    math(EXPR _shards "${ALEMBERT_TEST_SHARDS} * ${ARG_SHARD_WEIGHT}")
    math(EXPR _last "${_shards} - 1")
    set(_filter "*")
    if(ARG_LARGE)
      set(_filter "-${ARG_LARGE}")
      add_test(NAME ${name}.large COMMAND ${target} --gtest_filter=${ARG_LARGE})
      set_tests_properties(${name}.large PROPERTIES LABELS large COST ${ARG_SHARD_WEIGHT})
    endif()
    foreach(_shard RANGE ${_last})
      add_test(NAME ${name}.shard${_shard} COMMAND ${target} --gtest_filter=${_filter})
      set_tests_properties(${name}.shard${_shard} PROPERTIES
        LABELS "${ARG_LABELS}"
        COST ${ARG_SHARD_WEIGHT}
        ENVIRONMENT "GTEST_TOTAL_SHARDS=${_shards};GTEST_SHARD_INDEX=${_shard}")
    endforeach()
  elseif(ARG_LARGE)
    gtest_discover_tests(${target}
      DISCOVERY_TIMEOUT 60
      TEST_FILTER "-${ARG_LARGE}"
      PROPERTIES LABELS "${ARG_LABELS}")
    # one label only: gtest_discover_tests loses the separator of a list of labels on its way
    # into the generated file, where "eom large" reads as LABELS eom and a property `large`
    gtest_discover_tests(${target}
      DISCOVERY_TIMEOUT 60
      TEST_FILTER "${ARG_LARGE}"
      PROPERTIES LABELS large)
  else()
    gtest_discover_tests(${target}
      DISCOVERY_TIMEOUT 60
      PROPERTIES LABELS "${ARG_LABELS}")
  endif()
endfunction()
