# jl_core_part(NAME part SOURCES file... [USES part...] [LIBRARIES lib...])
#
# Declares the core part `part` as the static library jl_<part>. Its public
# headers are core/<part>/include/jl/<part>/*.h, included as
# "jl/<part>/file.h"; its sources and private headers sit in core/<part>/.
# Every part has an include root of its own, so code sees the public headers
# of exactly the parts it uses, directly or through another part, and an
# include across a missing link fails to compile.
#
# USES names the parts this one may use, each declared before it (so the
# links cannot form a circle); they are linked PUBLIC because their types
# appear in this part's headers. LIBRARIES names outside libraries, also
# PUBLIC. Every source is listed by name: a file added or renamed is a
# change to a list, never picked up (or dropped) silently by a pattern.
function(jl_core_part)
  cmake_parse_arguments(PARSE_ARGV 0 part "" "NAME" "SOURCES;USES;LIBRARIES")
  if(part_UNPARSED_ARGUMENTS OR NOT part_NAME OR NOT part_SOURCES)
    message(FATAL_ERROR "usage: jl_core_part(NAME part SOURCES file... [USES part...] [LIBRARIES lib...])")
  endif()
  set(target jl_${part_NAME})
  add_library(${target} STATIC ${part_SOURCES})
  target_include_directories(${target}
    PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  # The parts whose headers this one sees: itself and all it uses, directly
  # or through them (what the include wall check in tests/walls expects).
  set(sees ${part_NAME})
  foreach(used IN LISTS part_USES)
    if(NOT TARGET jl_${used})
      message(FATAL_ERROR "core part ${part_NAME} uses ${used}, which is not a part declared before it")
    endif()
    target_link_libraries(${target} PUBLIC jl_${used})
    get_property(used_sees GLOBAL PROPERTY JL_PART_SEES_${used})
    list(APPEND sees ${used_sees})
  endforeach()
  list(REMOVE_DUPLICATES sees)
  target_link_libraries(${target} PUBLIC ${part_LIBRARIES})
  jl_warnings(${target})
  set_property(GLOBAL APPEND PROPERTY JL_CORE_PARTS ${part_NAME})
  set_property(GLOBAL PROPERTY JL_PART_SEES_${part_NAME} ${sees})
  set_property(GLOBAL PROPERTY JL_PART_ROOT_${part_NAME} ${CMAKE_CURRENT_SOURCE_DIR}/include)
endfunction()
