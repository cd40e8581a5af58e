# voronav_add_module(NAME <m> [DEPS <modules...>] [PUBLIC_LIBS ...] [PRIVATE_LIBS ...])
#
# Builds voronav/<m>/*.cpp (without *_test.cpp) into the library voronav_<m>
# (alias voronav::<m>), installs its headers (not internal/), and builds the module's tests
# (*_test.cpp, GoogleTest) into voronav_<m>_tests, registered with CTest.
function(voronav_add_module)
  cmake_parse_arguments(M "" "NAME" "DEPS;PUBLIC_LIBS;PRIVATE_LIBS;TEST_LIBS" ${ARGN})
  set(dir ${CMAKE_CURRENT_SOURCE_DIR})
  file(GLOB_RECURSE all_cpp CONFIGURE_DEPENDS ${dir}/*.cpp)
  set(srcs "")
  set(tests "")
  foreach(f IN LISTS all_cpp)
    if(f MATCHES "_test\\.cpp$")
      list(APPEND tests ${f})
    else()
      list(APPEND srcs ${f})
    endif()
  endforeach()
  set(lib voronav_${M_NAME})
  add_library(${lib} ${srcs})
  add_library(voronav::${M_NAME} ALIAS ${lib})
  set_target_properties(${lib} PROPERTIES EXPORT_NAME ${M_NAME} OUTPUT_NAME voronav_${M_NAME})
  target_include_directories(${lib} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
                                           $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${lib} PUBLIC cxx_std_20)
  foreach(d IN LISTS M_DEPS)
    target_link_libraries(${lib} PUBLIC voronav_${d})
  endforeach()
  target_link_libraries(${lib} PUBLIC ${M_PUBLIC_LIBS} PRIVATE ${M_PRIVATE_LIBS})
  voronav_set_warnings(${lib})
  install(TARGETS ${lib} EXPORT voronavTargets
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/voronav/${M_NAME}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "internal" EXCLUDE)

  if(VORONAV_BUILD_TESTS AND tests)
    set(t voronav_${M_NAME}_tests)
    add_executable(${t} ${tests})
    target_link_libraries(${t} PRIVATE ${lib} ${M_TEST_LIBS} GTest::gtest GTest::gmock
                                       GTest::gtest_main)
    target_compile_definitions(${t} PRIVATE VORONAV_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
    voronav_set_warnings(${t})
    voronav_precompile(${t} tests <gtest/gtest.h> <algorithm> <cmath> <filesystem> <fstream>
                       <limits> <map> <random> <string> <vector>)
    gtest_discover_tests(${t} DISCOVERY_TIMEOUT 60 PROPERTIES LABELS ${M_NAME})
  endif()
endfunction()
