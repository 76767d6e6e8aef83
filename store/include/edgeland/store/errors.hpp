#pragma once
// The stores' error (store/README.md).
#include "edgeland/kernel/errors.hpp"
#include "edgeland/kernel/export.hpp"

namespace edgeland::store {

// A database failed (it could not be opened, a statement failed, a row is not what a store
// writes), or a commit was refused (a region this writer does not own). `what()` says which and
// names the database's own message.
class EDGELAND_EXPORT StoreError : public Error {
 public:
  using Error::Error;
};

}  // namespace edgeland::store
