# Writes OUT (a header) with the repository's commit, "+dirty" when the work tree has changes,
# or "unknown" outside a git checkout. Run at every build; configure_file rewrites OUT only when
# the text changes, so nothing recompiles unless the commit did.
cmake_minimum_required(VERSION 3.25)  # policies of a script run with -P
execute_process(COMMAND git -C "${SOURCE_DIR}" rev-parse HEAD OUTPUT_VARIABLE commit
                RESULT_VARIABLE failed OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(failed)
  set(commit "unknown")
else()
  execute_process(COMMAND git -C "${SOURCE_DIR}" diff --quiet HEAD RESULT_VARIABLE dirty
                  ERROR_QUIET)
  if(dirty)
    string(APPEND commit "+dirty")
  endif()
endif()
file(WRITE "${OUT}.in" "#pragma once\n#define MULTICPG_GIT_COMMIT \"@commit@\"\n")
configure_file("${OUT}.in" "${OUT}" @ONLY)
