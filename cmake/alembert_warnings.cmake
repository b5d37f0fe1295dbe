include_guard(GLOBAL)

# alembert_set_warnings(<target>): the project's warning set on <target>.
# GCC 12 at -O3 reports -Wrestrict on std::string concatenation inside libstdc++ (GCC bug
# 105329, a false positive), so that one warning is off for GCC 12.
function(alembert_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wnon-virtual-dtor
    $<IF:$<CXX_COMPILER_ID:GNU>,-Wshadow=local,-Wshadow-uncaptured-local>
    $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_GREATER_EQUAL:$<CXX_COMPILER_VERSION>,12>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict>
    $<$<BOOL:${ALEMBERT_WARNINGS_AS_ERRORS}>:-Werror>)
endfunction()
