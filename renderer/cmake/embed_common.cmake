# embed_common.cmake — shared by the embed_*.cmake scripts.

# Splits a text into C++ raw string literals of at most ~8000 characters (MSVC's literal
# limit is 16 KiB) that the compiler concatenates; "" for an empty text.
function(aerial_raw_string_pieces text delimiter out_var)
  string(LENGTH "${text}" length)
  set(pieces "")
  set(offset 0)
  while(offset LESS length)
    string(SUBSTRING "${text}" ${offset} 8000 piece)
    string(APPEND pieces "R\"${delimiter}(${piece})${delimiter}\"\n")
    math(EXPR offset "${offset} + 8000")
  endwhile()
  if(pieces STREQUAL "")
    set(pieces "\"\"")
  endif()
  set(${out_var} "${pieces}" PARENT_SCOPE)
endfunction()

# Writes `content` to `path` only when it differs, so dependants do not rebuild.
function(aerial_write_if_changed path content)
  set(previous "")
  if(EXISTS "${path}")
    file(READ "${path}" previous)
  endif()
  if(NOT previous STREQUAL content)
    file(WRITE "${path}" "${content}")
  endif()
endfunction()
