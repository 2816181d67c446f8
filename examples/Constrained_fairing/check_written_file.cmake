# Reads back a file that an example wrote: an OFF file with the vertex and face counts of the
# mesh it was made from, or a point file (.xyz, .pwn) with as many points as the one it was made
# from; and not that file unchanged.
#   cmake -DWRITTEN=FILE -DFROM=FILE -P check_written_file.cmake

# The counts of FILE: "OFF V F E" of an OFF file, comments left out, or the lines of a point file.
function(element_counts file out)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${file} was not written")
  endif()
  if(file MATCHES "\\.(xyz|pwn)$")
    file(STRINGS "${file}" lines REGEX "[0-9]")
    list(LENGTH lines count)
    set(${out} "${count} points" PARENT_SCOPE)
    return()
  endif()
  file(READ "${file}" head LIMIT 4096)
  string(REGEX REPLACE "#[^\n]*" "" head "${head}")
  if(NOT head MATCHES "^[ \t\r\n]*OFF[ \t\r\n]+([0-9]+)[ \t\r\n]+([0-9]+)[ \t\r\n]+[0-9]+")
    message(FATAL_ERROR "${file} does not start as an OFF file")
  endif()
  set(${out} "${CMAKE_MATCH_1} vertices, ${CMAKE_MATCH_2} faces" PARENT_SCOPE)
endfunction()

element_counts("${WRITTEN}" written)
element_counts("${FROM}" from)
if(NOT written STREQUAL from)
  message(FATAL_ERROR "${WRITTEN} has ${written}, ${FROM} ${from}")
endif()
file(SHA256 "${WRITTEN}" written_hash)
file(SHA256 "${FROM}" from_hash)
if(written_hash STREQUAL from_hash)
  message(FATAL_ERROR "${WRITTEN} is ${FROM} unchanged")
endif()
message(STATUS "${WRITTEN}: ${written}, as ${FROM}, moved")
