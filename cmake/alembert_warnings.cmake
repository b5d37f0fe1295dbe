include_guard(GLOBAL)

# alembert_set_warnings(<target>): the project's warning set on <target>.
function(alembert_set_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wshadow=local -Wnon-virtual-dtor
    $<$<BOOL:${ALEMBERT_WARNINGS_AS_ERRORS}>:-Werror>)
endfunction()
