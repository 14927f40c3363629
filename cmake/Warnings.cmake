# Per-target warning flags; -Werror only when EXACTMESH_WERROR is on (CI and the dev preset).
function(exactmesh_warnings target)
  target_compile_options(${target} PRIVATE
    -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wold-style-cast
    $<$<BOOL:${EXACTMESH_WERROR}>:-Werror>)
endfunction()
