# Precompiled headers for heavy third-party headers that many translation units parse: GoogleTest
# (every *_test.cpp, about 1.5 s of CPU each). They cut the CPU time of a cold build, which is what
# CI does (docs/ci.md; a CLI11 + nlohmann/json PCH for the CLI was measured and gave nothing).
# It is opt-in (-DVORONAV_PCH=ON): a shared PCH has not yet been through a full cold CI run, and
# ccache does not cache a translation unit that uses one unless its sloppiness is relaxed.
option(VORONAV_PCH "Precompile heavy third-party headers (GoogleTest) for the test executables" OFF)

# voronav_precompile(<target> <group> <header>...): the first target of a group compiles the
# headers into a PCH, later targets of the group reuse it (REUSE_FROM: they must be compiled with
# the same flags, which holds for all test executables of one build).
function(voronav_precompile target group)
  if(NOT VORONAV_PCH)
    return()
  endif()
  get_property(first GLOBAL PROPERTY VORONAV_PCH_${group})
  if(first)
    target_precompile_headers(${target} REUSE_FROM ${first})
  else()
    target_precompile_headers(${target} PRIVATE ${ARGN})
    set_property(GLOBAL PROPERTY VORONAV_PCH_${group} ${target})
  endif()
endfunction()
