# pb_set_warnings(target): the project's warning set, applied per target.
add_library(pb_warnings INTERFACE)
target_compile_options(pb_warnings INTERFACE
  $<$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion-null -Wnon-virtual-dtor>
  $<$<AND:$<COMPILE_LANG_AND_ID:CXX,GNU,Clang>,$<BOOL:${PB_WARNINGS_AS_ERRORS}>>:-Werror>)

add_library(pb_sanitizers INTERFACE)
if(PB_SANITIZE)
  target_compile_options(pb_sanitizers INTERFACE -fsanitize=${PB_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  target_link_options(pb_sanitizers INTERFACE -fsanitize=${PB_SANITIZE})
endif()

function(pb_set_warnings target)
  target_link_libraries(${target} PRIVATE pb_warnings pb_sanitizers)
endfunction()
