// The number types a scheme kernel is written for. A kernel written as a template on its
// scalar S runs one body with S = double, and `Pack::size` bodies at once with S = Pack
// (xsimd, AVX2 + FMA: four doubles), from the same source. The batched loops use the pack
// for whole groups of bodies and double for the rest, so every scene of fewer than four
// bodies, and every build without AVX2, runs the double code only.
//
// The pack's sin and cos are xsimd's, not glibc's: they agree to about an ulp, not bit for
// bit. Only rotations of more than a radian in one step call them (schemes/quaternion.hpp);
// below that, a body stepped in a pack gets the same bits as the same body stepped alone.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#if defined(__AVX2__) && defined(__FMA__) && __has_include(<xsimd/xsimd.hpp>)
#include <xsimd/xsimd.hpp>
#define ROTBENCH_SIMD 1
namespace rotbench {
using Pack = xsimd::batch<double, xsimd::fma3<xsimd::avx2>>;
inline constexpr std::size_t pack_size = Pack::size;
inline Pack select(const Pack::batch_bool_type& condition, const Pack& if_true, const Pack& if_false) {
    return xsimd::select(condition, if_true, if_false);
}
inline std::pair<Pack, Pack> sin_cos(const Pack& x) { return xsimd::sincos(x); }  // one range reduction for both
inline bool any_lane(const Pack::batch_bool_type& condition) { return xsimd::any(condition); }
inline Pack::batch_bool_type is_finite(const Pack& x) { return xsimd::isfinite(x); }
// f, a function of doubles, applied to each lane: the bits of the bodies stepped alone.
template <class F>
Pack each_lane(const Pack& x, F&& f) {
    alignas(Pack::arch_type::alignment()) double v[Pack::size];
    x.store_aligned(v);
    for (double& e : v) e = f(e);
    return Pack::load_aligned(v);
}
}  // namespace rotbench

// Eigen's matrices and quaternions of packs: the pack is a real number type, and a double
// times a pack is a pack.
namespace Eigen {
template <>
struct NumTraits<rotbench::Pack> : GenericNumTraits<double> {
    using Real = rotbench::Pack;
    using NonInteger = rotbench::Pack;
    using Nested = rotbench::Pack;
    using Literal = double;
    enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 1, ReadCost = 1, AddCost = 1, MulCost = 1 };
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<double, rotbench::Pack, BinaryOp> {
    using ReturnType = rotbench::Pack;
};
template <typename BinaryOp>
struct ScalarBinaryOpTraits<rotbench::Pack, double, BinaryOp> {
    using ReturnType = rotbench::Pack;
};
}  // namespace Eigen
#else
#define ROTBENCH_SIMD 0
namespace rotbench {
inline constexpr std::size_t pack_size = 1;  // no packs: one body at a time
}
#endif

// The frame helpers are a few dozen flops each and run several times per body-step: a call
// costs as much as their work, and as templates GCC no longer inlines them on its own.
#define ROTBENCH_INLINE [[gnu::always_inline]] inline

namespace rotbench {

inline double select(bool condition, double if_true, double if_false) { return condition ? if_true : if_false; }
inline std::pair<double, double> sin_cos(double x) { return {std::sin(x), std::cos(x)}; }  // GCC calls sincos
inline bool any_lane(bool condition) { return condition; }  // a pack's lane, or the one body
inline bool is_finite(double x) { return std::isfinite(x); }
template <class F>
double each_lane(double x, F&& f) { return f(x); }

// The condition of every lane: true for one body, all lanes true for a pack.
template <class S>
auto all_true() {
    if constexpr (std::is_same_v<S, double>) return true;
    else return S(0.0) == S(0.0);
}

template <class S>
using Vec3T = Eigen::Matrix<S, 3, 1>;
template <class S>
using QuatT = Eigen::Quaternion<S>;

// Per lane: `if_true` where the condition holds, `if_false` elsewhere.
template <class S, class Condition>
ROTBENCH_INLINE Vec3T<S> select(const Condition& condition, const Vec3T<S>& if_true, const Vec3T<S>& if_false) {
    return {select(condition, if_true.x(), if_false.x()), select(condition, if_true.y(), if_false.y()),
            select(condition, if_true.z(), if_false.z())};
}

}  // namespace rotbench
