// A transient's cast to an OCCT class it may be: OCCT's own type test (IsKind, a walk up the
// Standard_Type parents) where dynamic_cast's failed casts cost ~350 instructions each.
#pragma once
#include <Standard_Transient.hxx>
#include <Standard_Type.hxx>

namespace tessera::cad_detail {

// `object` as a T (or a class derived from it), else null; null for null.
template <typename T>
const T* kindOf(const Standard_Transient* object) {
  return object && object->IsKind(STANDARD_TYPE(T)) ? static_cast<const T*>(object) : nullptr;
}

}  // namespace tessera::cad_detail
