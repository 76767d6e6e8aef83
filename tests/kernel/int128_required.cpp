// Compiled by ctest (kernel.int128_required) as a compiler without 128-bit integers would see
// it (__SIZEOF_INT128__ undefined): the kernel's headers must stop with their one-line reason,
// not with an error deep inside a template.
#include "edgeland/kernel/predicates.hpp"

int main() { return 0; }
