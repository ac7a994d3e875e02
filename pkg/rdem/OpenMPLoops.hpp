/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* What the plugin's OpenMP loops share: how many threads an engine's loop runs on, and a sum of Real over a loop. */
#pragma once

#include <lib/base/Math.hpp>
#ifdef YADE_OPENMP
#include <algorithm>
#include <omp.h>
#endif

namespace yade {
namespace rdem {
	/// Threads for a loop of an engine with the given Engine::ompThreads: that many if > 0 (at most the available),
	/// else all, as YADE's InteractionLoop does.
	inline int threadsFor(int ompThreads)
	{
#ifdef YADE_OPENMP
		return ompThreads > 0 ? std::min(ompThreads, omp_get_max_threads()) : omp_get_max_threads();
#else
		(void)ompThreads;
		return 1;
#endif
	}
} // namespace rdem

#ifdef YADE_OPENMP
/* reduction(realSum : x): a sum of Real over an OpenMP loop. OpenMP's reduction(+ : x) needs a built-in type, and Real
   is a class in YADE's long-double, float128 and MPFR builds; a reduction declared under a name of its own is valid for
   every type, double included. */
#pragma omp declare reduction(realSum:Real : omp_out += omp_in) initializer(omp_priv = Real(0))
#endif

} // namespace yade
