// What Box2D 2.4.1 cannot be given, and how a Box2D run stops following the
// case. Debian's libbox2d keeps its asserts (b2Assert is assert, b2_common.h),
// which abort the whole process: every input that would reach one is refused
// before Box2D sees it (EngineError), and every step is checked so that a
// runaway stops the run before it feeds Box2D non-finite numbers.
//
// Box2D clamps each step's translation to b2_maxTranslation = 2 m and its
// rotation to b2_maxRotation = pi/2 (b2_island.cpp, "Check for large
// velocities"): a runaway there does not reach inf, it looks like a body
// leaving the scene at 2 m per step. A velocity at the clamp is therefore a
// fault too, and so is one so large that h v squared overflows float inside
// the clamp, where Box2D scales the velocity by 2 / inf = 0 and the body stops
// dead without a trace.
#pragma once

#include <box2d/b2_body.h>

#include <string>

#include "planarbench/case.hpp"
#include "planarbench/engine.hpp"

namespace pb::internal::box2d {

// Why Box2D must not get this case at step dt_s ("" when it may): a moving
// body's mass or inertia outside float's normal range (b2Body::SetMassData
// asserts m_I > 0, which inf fails; a mass that rounds to 0 becomes 1 kg), a
// non-finite pose, a velocity or a gravity that Box2D would clamp in the
// first step, or that overflows float (b2Body's constructor asserts a valid
// velocity).
[[nodiscard]] std::string refused_input_reason(const Case& c, double dt_s);

// Why a body's velocity after a step (its state s) shows Box2D's clamp ("" when it does
// not): |v| h or |omega| h within 1e-5 of b2_maxTranslation or b2_maxRotation
// (the clamp leaves exactly that, up to float rounding), or beyond it (a TOI
// sub-step clamps with its shorter h).
[[nodiscard]] std::string clamped_velocity_reason(const BodyState& s, double dt_s);

// Why an injected force would make Box2D clamp this body in the coming step
// ("" when not): the velocity after the step, v + h (g + F / m) and
// omega + h tau / I, checked in double before Box2D computes it in float.
// force_n and torque_nm are the totals the adapter applies to the body
// (torque about its centre of mass).
[[nodiscard]] std::string injected_force_reason(const b2Body& body, const Body& case_body,
                                                const Vec2& gravity_mps2, const Vec2& force_n,
                                                double torque_nm, double dt_s);

}  // namespace pb::internal::box2d
