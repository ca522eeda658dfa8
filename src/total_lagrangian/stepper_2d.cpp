#include "total_lagrangian/stepper_2d.hpp"

#include "total_lagrangian/ghost_reflection.hpp"
#include "total_lagrangian/laws.hpp"
#include "total_lagrangian/variational_closure.hpp"

namespace sph {

namespace {
template <class T>
struct Type { using type = T; };
}  // namespace

std::unique_ptr<TlStepper2D> make_tl_stepper_2d(const TlBody2D& b, HourglassControl hg) {
  const bool hourglass = b.cfg.hourglass > 0, damping = b.cfg.damping > 0;
  auto with_passes = [&](auto law, auto closure) -> std::unique_ptr<TlStepper2D> {
    using L = typename decltype(law)::type;
    using C = typename decltype(closure)::type;
    if (hourglass && damping) return std::make_unique<TlStepperOf<L, C, true, true>>(b, std::move(hg));
    if (hourglass) return std::make_unique<TlStepperOf<L, C, true, false>>(b, std::move(hg));
    if (damping) return std::make_unique<TlStepperOf<L, C, false, true>>(b, std::move(hg));
    return std::make_unique<TlStepperOf<L, C, false, false>>(b, std::move(hg));
  };
  auto with_closure = [&](auto law) {
    return b.cfg.closure == TlConfig2D::Closure::Variational ? with_passes(law, Type<VariationalClosure>{})
                                                             : with_passes(law, Type<GhostReflection>{});
  };
  return b.cfg.law == TlConfig2D::Law::NeoHookean ? with_closure(Type<NeoHookeanLaw>{}) : with_closure(Type<HookeLaw>{});
}

}  // namespace sph
