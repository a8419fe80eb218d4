# cmake/embed_file.cmake: a file as a C array, at build time.
#   cmake -DIN=FILE -DOUT=FILE.c -DNAME=symbol -P embed_file.cmake
# writes `const unsigned char NAME[]` (the bytes of IN, then a NUL not counted) and
# `const unsigned long NAME_len`. Bytes, not a string literal: C caps a
# literal at 4095 characters and the page is longer.
file(READ "${IN}" hex HEX)
string(LENGTH "${hex}" n)
math(EXPR len "${n} / 2")
string(REGEX REPLACE "([0-9a-f][0-9a-f])" "0x\\1," bytes "${hex}")
# 16 bytes a line
string(REGEX REPLACE "((0x[0-9a-f][0-9a-f],){16})" "\\1\n    " bytes "${bytes}")
file(WRITE "${OUT}.tmp"
  "/* generated from ${IN} by cmake/embed_file.cmake: do not edit */\n"
  "const unsigned char ${NAME}[] = {\n    ${bytes}0x00};\n"
  "const unsigned long ${NAME}_len = ${len}UL;\n")
file(RENAME "${OUT}.tmp" "${OUT}")
