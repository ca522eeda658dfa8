// Particle states are structures of arrays: one std::vector per field, all of one length. A state lists its
// fields once, in fields() (a std::tie of them, with a const overload), and whatever must touch every field
// is written once, here, against that list:
//   for_each_field(s, f)           f(field) for every field
//   zip_fields(f, s1, s2, ...)     f(field of s1, the same field of s2, ...) for every field
//   resize_fields(s, n)            every field to n entries
//   Reorder::apply(s, order)       every field permuted, new[i] = old[order[i]] (e.g. along a space-filling
//                                  curve, space_filling.hpp), in place; no allocation once sized
//   FieldAlgebra<State>            out = a + s k and y += s k over every field: what RK4 needs of a state
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace sph {

template <class State, class F>
void for_each_field(State& s, F&& f) {
  std::apply([&](auto&... field) { (f(field), ...); }, s.fields());
}

namespace detail {
template <std::size_t I, class F, class... Tuples>
void call_at(F& f, Tuples&... t) {
  f(std::get<I>(t)...);
}
template <class F, std::size_t... I, class... Tuples>
void zip_tuples(F& f, std::index_sequence<I...>, Tuples... t) {
  (call_at<I>(f, t...), ...);
}
}  // namespace detail

template <class F, class State, class... More>
void zip_fields(F&& f, State& s, More&... more) {
  constexpr std::size_t n = std::tuple_size_v<std::decay_t<decltype(s.fields())>>;
  detail::zip_tuples(f, std::make_index_sequence<n>{}, s.fields(), more.fields()...);
}

/// The zero of a field's element type: 0 for numbers and enums, T::Zero() for Eigen types.
template <class T>
T zero_of() {
  if constexpr (std::is_arithmetic_v<T> || std::is_enum_v<T>) return T{};
  else return T::Zero();
}

/// Every field to n entries; new entries are zero.
template <class State>
void resize_fields(State& s, std::size_t n) {
  for_each_field(s, [n](auto& field) { field.resize(n, zero_of<typename std::decay_t<decltype(field)>::value_type>()); });
}

/// The number of particles of a state: the length of its first field.
template <class State>
std::size_t field_size(const State& s) {
  return std::get<0>(s.fields()).size();
}

/// Applies one permutation to every field of a state, in place, cycle by cycle (any copyable element type,
/// Eigen's included); its only scratch, one flag per particle, is kept between calls.
class Reorder {
 public:
  template <class State>
  void apply(State& s, const std::vector<std::uint32_t>& order) {
    for_each_field(s, [&](auto& field) { permute(field, order); });
  }

 private:
  template <class T>
  void permute(std::vector<T>& field, const std::vector<std::uint32_t>& order) {
    const std::size_t n = field.size();
    if (order.size() != n) throw std::invalid_argument("Reorder: the order must have one entry per particle");
    done_.assign(n, 0);
    for (std::size_t start = 0; start < n; ++start) {
      if (done_[start]) continue;
      T first = field[start];
      std::size_t i = start;
      for (std::size_t j = order[i]; j != start; i = j, j = order[j]) {
        field[i] = field[j];
        done_[i] = 1;
      }
      field[i] = first;
      done_[i] = 1;
    }
  }
  std::vector<unsigned char> done_;
};

/// The vector-space operations of a state over all its fields, element by element (no allocation):
/// set_axpy(out, a, s, k): out = a + s k;  axpy(y, s, k): y += s k. For std::vector fields of double or of
/// fixed-size Eigen types.
struct FieldAlgebra {
  template <class State>
  static void set_axpy(State& out, const State& a, double s, const State& k) {
    zip_fields([s](auto& o, const auto& x, const auto& d) {
      const std::size_t n = x.size();
      for (std::size_t i = 0; i < n; ++i) o[i] = x[i] + s * d[i];
    }, out, a, k);
  }
  template <class State>
  static void axpy(State& y, double s, const State& k) {
    zip_fields([s](auto& o, const auto& d) {
      const std::size_t n = o.size();
      for (std::size_t i = 0; i < n; ++i) o[i] += s * d[i];
    }, y, k);
  }
};

}  // namespace sph
