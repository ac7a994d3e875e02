/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Random properties per bond: lognormal factors of mean 1 and a given coefficient of variation, drawn from a
   counter-based generator keyed by (seed, the bond's two body ids, a stream number), so that a bond's factor does not
   depend on the order in which bonds are made, on threads, or on O.load: a fixed seed reproduces a scene bit for bit.

   Generator: SplitMix64 (Steele, Lea & Flood 2014, "Fast splittable pseudorandom number generators", OOPSLA '14;
   doc/references.bib Steele2014), applied to a combination of the key's parts; two uniforms give one standard normal by
   the Box–Muller transform. Distribution: lognormal, X = exp(μ + s Z), s² = ln(1 + v²), μ = -s²/2, so that E[X] = 1 and
   the coefficient of variation std[X]/E[X] = v exactly; X > 0 always (a strength or stiffness never turns negative, as a
   truncated normal would need to be cut for). */
#pragma once

#include <cmath>
#include <cstdint>

namespace yade {
namespace rdem {

	/// SplitMix64's output function of the state x (one step of the generator) [Steele2014].
	inline std::uint64_t splitMix64(std::uint64_t x)
	{
		x += 0x9E3779B97F4A7C15ull;
		x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
		x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
		return x ^ (x >> 31);
	}

	/// A uniform number in (0, 1) for the key (seed, a, b, stream): the top 53 bits of the hash, offset by half a unit so
	/// that neither 0 nor 1 occurs.
	inline double keyedUniform(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t stream)
	{
		const std::uint64_t h = splitMix64(splitMix64(splitMix64(splitMix64(seed) ^ a) ^ b) ^ stream);
		return (double(h >> 11) + 0.5) * 0x1.0p-53;
	}

	/// A standard normal number for the key (Box–Muller on the streams 2·stream and 2·stream + 1).
	inline double keyedNormal(std::uint64_t seed, std::uint64_t a, std::uint64_t b, std::uint64_t stream)
	{
		const double u1 = keyedUniform(seed, a, b, 2 * stream), u2 = keyedUniform(seed, a, b, 2 * stream + 1);
		return std::sqrt(-2 * std::log(u1)) * std::cos(2 * 3.14159265358979323846 * u2);
	}

	/// Lognormal factor of mean 1 and coefficient of variation cov ≥ 0 for the standard normal z: exp(μ + s z) (see above).
	template <class S> S lognormalFactor(S cov, S z)
	{
		using std::exp;
		using std::log;
		using std::sqrt;
		const S s2 = log(1 + cov * cov);
		return exp(-s2 / 2 + sqrt(s2) * z);
	}

} // namespace rdem
} // namespace yade
