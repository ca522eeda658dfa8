// The part of a store-of-runs key (frame/run_store.hpp) that Gray's scheme contributes: every parameter and
// switch of the scheme, exactly. The plate's and the slab's stored runs (plate_run_cache, slab_store) share it.
#pragma once

#include <string>

#include "updated_lagrangian/parameters.hpp"

namespace scenes {

std::string gray_scheme_key(const sph::GrayParameters& g, const sph::GrayOptions& o);

}  // namespace scenes
