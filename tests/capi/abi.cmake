# The C ABI only grows (edgeland.h, CONVENTIONS): the library is compared with the committed
# baseline by abidiff (abigail-tools); --no-added-syms leaves additions out, so any other change
# (a function removed, a parameter or a struct changed, a field appended: a struct_size-prefixed
# struct may grow, an array element may not, and abidiff cannot tell them apart, so each growth
# is recorded in the baseline on purpose) fails with abidiff's report.
# To record a new baseline after adding functions: scripts/update_capi_abi.sh.
execute_process(COMMAND abidiff --no-added-syms ${BASELINE} ${LIBRARY}
  OUTPUT_VARIABLE report ERROR_VARIABLE report RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "abidiff exit ${rc} (4: ABI change, 8: incompatible change):\n${report}")
endif()
message(STATUS "ABI as the baseline ${BASELINE} (additions aside)")
