/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <core/Body.hpp>
#include <core/BodyContainer.hpp>
#include <core/State.hpp>
#include <pkg/rdem/Ig2_RdemBlock_RdemBlock_RdemGeom.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/RdemPrefetch.hpp>
#include <cstdint>
#include <fstream>
#include <string>

namespace yade {
namespace rdem {

	namespace {
		/// A read prefetch of the cache line holding p: GCC's and Clang's builtin; with other compilers nothing (a prefetch
		/// is a hint only, results do not depend on it).
		inline void prefetchLine(const void* p)
		{
#if defined(__GNUC__) || defined(__clang__)
			__builtin_prefetch(p);
#else
			(void)p;
#endif
		}

		/// Ask for the cache lines that hold the bytes [begin, end) (read access).
		void prefetchBytes(const void* begin, const void* end)
		{
			constexpr std::uintptr_t cacheLine = 64; // bytes: x86-64 and most ARM cores
			const auto               last      = reinterpret_cast<std::uintptr_t>(end);
			for (auto line = reinterpret_cast<std::uintptr_t>(begin) & ~(cacheLine - 1); line < last; line += cacheLine)
				prefetchLine(reinterpret_cast<const void*>(line));
		}

		template <class T> void prefetchObject(const T* p)
		{
			if (p) prefetchBytes(p, p + 1);
		}

		/* Bytes from the start of an RdemGeom (RdemPhys) to the end of the last attribute the law reads for a bond
		   (RdemGeom::normal, RdemPhys::segTau; the attributes are laid out for this), taken from an object made once, so
		   that the range is known before the object to fetch is in the cache. */
		std::uintptr_t bytesUpTo(const Serializable& object, const void* end)
		{
			return reinterpret_cast<std::uintptr_t>(end) - reinterpret_cast<std::uintptr_t>(&object);
		}
		std::uintptr_t hotGeomBytes()
		{
			static const std::uintptr_t bytes = [] {
				const RdemGeom g;
				return bytesUpTo(g, &g.normal + 1);
			}();
			return bytes;
		}
		std::uintptr_t hotPhysBytes()
		{
			static const std::uintptr_t bytes = [] {
				const RdemPhys p;
				return bytesUpTo(p, &p.segTau + 1);
			}();
			return bytes;
		}

		/// The first bytes of an object of any type (a prefetch past the end of a smaller object is harmless).
		void prefetchFirst(const void* p, std::uintptr_t bytes)
		{
			if (p) prefetchBytes(p, static_cast<const char*>(p) + bytes);
		}

		/// The part of a body's State the law and the geometry functor read: position, orientation, velocities.
		void prefetchState(const Body* b)
		{
			if (!b || !b->state) return;
			const State* s = b->state.get();
			prefetchBytes(s, &s->angVel + 1);
		}
	}

	size_t lastLevelCacheBytes()
	{
		/* The cache of the highest level CPU 0 has, as Linux describes it (/sys/devices/system/cpu/cpu0/cache/index*:
		   level, size such as "32768K"): the cache one core can use. glibc's sysconf(_SC_LEVEL3_CACHE_SIZE) adds up the
		   L3 of all core complexes of an AMD processor (12 complexes of 32 MiB give 384 MiB), too much for this use.
		   Elsewhere than on Linux, and if sysfs says nothing: 32 MiB. */
		size_t bytes = 0;
#ifdef __linux__
		int level = 0;
		for (int index = 0; index < 16; ++index) {
			const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index) + "/";
			std::ifstream     levelFile(dir + "level"), sizeFile(dir + "size");
			int               l    = 0;
			size_t            size = 0;
			char              unit = 0;
			if (!(levelFile >> l) || !(sizeFile >> size) || l <= level) continue;
			sizeFile >> unit;
			level = l;
			bytes = size * (unit == 'K' ? 1024 : unit == 'M' ? 1024 * 1024 : 1);
		}
#endif
		return bytes > 0 ? bytes : size_t(32) << 20;
	}

	void prefetchInteractionsAhead(Scene& scene, const Interaction& current, int distance)
	{
		if (distance <= 0) return;
		auto&      intrs = *scene.interactions;
		const long size  = long(intrs.size());
		const long index = current.linIx; // not set (any value) before the interaction enters the container
		if (index < 0 || index >= size || intrs[index].get() != &current) return;
		const auto& bodies = scene.bodies->body;
		const long  far = index + 2 * long(distance), near = index + distance, nearer = index + math::max(distance / 2, 1);
		if (far < size) prefetchObject(intrs[far].get());
		if (near < size) {
			const Interaction& J = *intrs[near];
			// A potential pair (no physics) has at most an RdemGap, which the geometry functor reads whole.
			prefetchFirst(J.geom.get(), J.phys ? hotGeomBytes() : sizeof(RdemGap));
			prefetchFirst(J.phys.get(), hotPhysBytes());
			prefetchObject(bodies[size_t(J.getId1())].get());
			prefetchObject(bodies[size_t(J.getId2())].get());
		}
		if (nearer < size) {
			const Interaction& J = *intrs[nearer];
			if (J.phys && J.phys->getClassIndex() == RdemPhys::getClassIndexStatic()) {
				const auto& p = static_cast<const RdemPhys&>(*J.phys);
				prefetchBytes(p.segState.data(), p.segState.data() + p.segState.size());
				prefetchBytes(p.segSigma.data(), p.segSigma.data() + p.segSigma.size());
				prefetchBytes(p.segTau.data(), p.segTau.data() + p.segTau.size());
			}
			prefetchState(bodies[size_t(J.getId1())].get());
			prefetchState(bodies[size_t(J.getId2())].get());
		}
	}

} // namespace rdem
} // namespace yade
