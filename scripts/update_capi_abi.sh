#!/usr/bin/env bash
# Records the C API's ABI baseline (capi/abi/edgeland_c.abi) from a built libedgeland_c.so,
# after functions or fields were ADDED to edgeland.h (ctest capi.abi refuses every other change).
# Usage: scripts/update_capi_abi.sh [BUILD_DIR]   (default build/test)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build/test}"
abidw --headers-dir capi/include/edgeland --drop-private-types --exported-interfaces-only \
  --no-comp-dir-path --no-corpus-path --short-locs --no-show-locs \
  --out-file capi/abi/edgeland_c.abi "$build/capi/libedgeland_c.so"
echo "capi/abi/edgeland_c.abi: $(grep -c '<function-decl' capi/abi/edgeland_c.abi) functions"
