// Undoing the creation of a store: a command that created a store and then failed removes it, so
// that it leaves no store behind (as it leaves an existing store as it was).
#pragma once

#include <memory>

#include "store/store.h"

namespace maquette {

// Closes the store and, if this open created it (Store::created), removes its files (the store,
// its WAL, shared memory and journal). Throws nothing.
void remove_if_created(std::unique_ptr<Store> store) noexcept;

}  // namespace maquette
