# Writes each ```cpp block of a Markdown file to OUT/PREFIX_N.cpp as a program: the block's
# #include and `using namespace` lines at file scope, every other line inside main(), which
# returns 0 when the block ran through (an exception escaping it fails the test).
# Usage: awk -v out=DIR -v prefix=NAME -f extract_cpp_blocks.awk FILE.md
/^```cpp[ \t]*$/ { n++; inside = 1; head = ""; body = ""; next }
inside && /^```/ {
  file = out "/" prefix "_" n ".cpp"
  printf "// Extracted from the README by tests/readme/extract_cpp_blocks.awk.\n%s\nint main() {\n%s  return 0;\n}\n", head, body > file
  close(file)
  inside = 0
  next
}
inside && /^(#include|using namespace)/ { head = head $0 "\n"; next }
inside { body = body "  " $0 "\n" }
