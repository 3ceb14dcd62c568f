# Common settings for every ferrodyn target.
add_library(ferro_options INTERFACE)
target_compile_options(ferro_options INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wno-unused-parameter>)
if(FERRO_SANITIZE)
  target_compile_options(ferro_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  target_link_options(ferro_options INTERFACE -fsanitize=address,undefined)
endif()
if(FERRO_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FERRO_FUZZ needs clang: configure with -DCMAKE_C_COMPILER=clang "
                        "-DCMAKE_CXX_COMPILER=clang++ (see tools/fuzz.sh)")
  endif()
  # Coverage instrumentation for every project library; the fuzz targets link libFuzzer.
  target_compile_options(ferro_options INTERFACE -fsanitize=fuzzer-no-link,address
    -fno-omit-frame-pointer)
  target_link_options(ferro_options INTERFACE -fsanitize=address)
endif()

# ferro_add_library(<folder> DEPS <targets...>)
# One library per top-level folder: sources in <folder>/src (recursively), public
# headers in <folder>/include/ferro/<folder>. Exported as ferro::<folder>.
function(ferro_add_library folder)
  cmake_parse_arguments(ARG "" "" "DEPS;PRIVATE_DEPS" ${ARGN})
  file(GLOB_RECURSE _srcs CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp)
  set(_target ferro_${folder})
  if(_srcs)
    add_library(${_target} ${_srcs})
    set_target_properties(${_target} PROPERTIES EXPORT_NAME ${folder} OUTPUT_NAME ferro_${folder})
    target_include_directories(${_target} PUBLIC
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${_target} PUBLIC ${ARG_DEPS} PRIVATE ferro_options ${ARG_PRIVATE_DEPS})
  else()
    # Header-only for now (no sources yet in this folder).
    add_library(${_target} INTERFACE)
    set_target_properties(${_target} PROPERTIES EXPORT_NAME ${folder})
    target_include_directories(${_target} INTERFACE
      $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
      $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
    target_link_libraries(${_target} INTERFACE ${ARG_DEPS})
  endif()
  add_library(ferro::${folder} ALIAS ${_target})
  set_property(GLOBAL APPEND PROPERTY FERRO_LIBRARIES ${_target})
endfunction()
