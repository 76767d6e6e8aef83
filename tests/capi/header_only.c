/* edgeland.h alone, compiled as C99 -pedantic -Werror for other targets (ctest capi.layout_*):
 * its layout asserts then hold there too. */
#include "edgeland/edgeland.h"

int el_header_only_unused(void);
int el_header_only_unused(void) { return (int)sizeof(el_error); }
