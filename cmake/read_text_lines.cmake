# Reading text into CMake lists safely. CMake does not split a list at a ';' inside square
# brackets or after a '\', so one unbalanced '[' (a half-open interval "[0, 1)" in a comment)
# would merge every later line into one element. These helpers replace the four characters by
# control characters that text files do not hold, and put them back for printing.
string(ASCII 1 text_backslash)
string(ASCII 2 text_semicolon)
string(ASCII 3 text_open_bracket)
string(ASCII 4 text_close_bracket)

# encode_text(<variable>): the variable's text, with the four characters replaced.
function(encode_text variable)
  set(text "${${variable}}")
  if(text MATCHES "[${text_backslash}${text_semicolon}${text_open_bracket}${text_close_bracket}]")
    message(FATAL_ERROR "encode_text: the text holds a control character 1-4")
  endif()
  string(REPLACE "\\" "${text_backslash}" text "${text}")
  string(REPLACE ";" "${text_semicolon}" text "${text}")
  string(REPLACE "[" "${text_open_bracket}" text "${text}")
  string(REPLACE "]" "${text_close_bracket}" text "${text}")
  set(${variable} "${text}" PARENT_SCOPE)
endfunction()

# decode_text(<variable>): undoes encode_text.
function(decode_text variable)
  set(text "${${variable}}")
  string(REPLACE "${text_backslash}" "\\" text "${text}")
  string(REPLACE "${text_semicolon}" ";" text "${text}")
  string(REPLACE "${text_open_bracket}" "[" text "${text}")
  string(REPLACE "${text_close_bracket}" "]" text "${text}")
  set(${variable} "${text}" PARENT_SCOPE)
endfunction()

# read_text_lines(<file> <variable>): the file's encoded lines, one list element each (line n is
# element n - 1; empty lines are kept).
function(read_text_lines file variable)
  file(READ "${file}" text)
  encode_text(text)
  string(REPLACE "\r" "" text "${text}")
  string(REPLACE "\n" ";" text "${text}")
  set(${variable} "${text}" PARENT_SCOPE)
endfunction()
