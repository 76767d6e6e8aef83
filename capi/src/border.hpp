#pragma once
// The border between C and C++ (STYLE.md 17): every entry point of edgeland.h runs its body
// through execute(), which catches everything and turns it into an el_status and, when the
// caller asked for one, an el_error with the error's fields. Nothing else in capi/ catches.
#include <cstddef>
#include <cstring>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

#include "edgeland/edgeland.h"

namespace edgeland::capi {

// An error of the border itself (a NULL argument, an index past the end, an unknown
// struct_size, a buffer too small): a status without a C++ class behind it.
class BorderError : public std::runtime_error {
 public:
  BorderError(el_status code, const std::string& what) : std::runtime_error(what), status(code) {}
  el_status status;
};

// The status of the exception being handled, its fields written to *error (if not NULL).
el_status translate_current_exception(el_error* error) noexcept;

// Runs body; EL_OK, or the translated exception.
template <class Body>
el_status execute(el_error* error, Body&& body) noexcept {
  try {
    std::forward<Body>(body)();
    return EL_OK;
  } catch (...) {
    return translate_current_exception(error);
  }
}

// A required pointer argument: *p, or EL_NULL_ARGUMENT naming it.
template <class T>
T& need(T* p, const char* name) {
  if (p == nullptr) throw BorderError(EL_NULL_ARGUMENT, std::string(name) + " is NULL");
  return *p;
}

// A struct the caller sized (struct_size first): the library's defaults overwritten by the
// caller's bytes. A size this library does not know (0, or beyond its own struct) is
// EL_VERSION_MISMATCH: fields are only ever appended, so a larger struct asks for more than this
// library can honour.
template <class T>
T read_sized(const T& given, const T& defaults) {
  const std::uint32_t size = given.struct_size;
  if (size < sizeof(std::uint32_t) || size > sizeof(T)) {
    throw BorderError(EL_VERSION_MISMATCH, "struct_size " + std::to_string(size) +
                                               " unknown to this library (expected at most " +
                                               std::to_string(sizeof(T)) + ")");
  }
  T out = defaults;
  std::memcpy(static_cast<void*>(&out), static_cast<const void*>(&given), size);
  return out;
}

// Writes a struct the caller sized: at most its struct_size bytes, struct_size kept.
template <class T>
void write_sized(T* dest, T value) {
  const std::uint32_t size = dest->struct_size;
  value.struct_size = size;
  std::memcpy(static_cast<void*>(dest), static_cast<const void*>(&value),
              size < sizeof(T) ? size : sizeof(T));
}

}  // namespace edgeland::capi
