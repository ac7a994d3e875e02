/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* How the plugin's engines and functors find each other in a scene: by type, in O.engines and in the dispatchers of its
   InteractionLoops. One copy of the scans, so that each caller says what it looks for and not how. */
#pragma once

#include <core/Dispatching.hpp>
#include <core/InteractionLoop.hpp>
#include <core/Scene.hpp>
#include <type_traits>

namespace yade {
namespace rdem {

	/// The first engine of type T (or derived) in scene->engines, or nullptr.
	template <class T> T* findEngine(const Scene* scene)
	{
		for (const auto& e : scene->engines)
			if (auto* t = dynamic_cast<T*>(e.get())) return t;
		return nullptr;
	}

	/// Position of the first engine of type T (or derived) in scene->engines, or -1.
	template <class T> long engineIndex(const Scene* scene)
	{
		for (size_t i = 0; i < scene->engines.size(); ++i)
			if (dynamic_cast<T*>(scene->engines[i].get())) return long(i);
		return -1;
	}

	/// Position of the engine e in scene->engines, or -1 (e null or not there).
	inline long positionOf(const Scene* scene, const Engine* e)
	{
		for (size_t i = 0; i < scene->engines.size(); ++i)
			if (e && scene->engines[i].get() == e) return long(i);
		return -1;
	}

	/// Calls f(T&) for every engine of type T (or derived) in scene->engines, in their order.
	template <class T, class F> void forEachEngine(const Scene* scene, F f)
	{
		for (const auto& e : scene->engines)
			if (auto* t = dynamic_cast<T*>(e.get())) f(*t);
	}

	/// Calls f(T&) for every functor of type T in the InteractionLoops of scene->engines: T an IGeomFunctor, an
	/// IPhysFunctor or a LawFunctor, searched in the loop's dispatcher of that kind.
	template <class T, class F> void forEachLoopFunctor(const Scene* scene, F f)
	{
		static_assert(
		        std::is_base_of<IGeomFunctor, T>::value || std::is_base_of<IPhysFunctor, T>::value || std::is_base_of<LawFunctor, T>::value,
		        "forEachLoopFunctor: T must be an IGeomFunctor, IPhysFunctor or LawFunctor");
		forEachEngine<InteractionLoop>(scene, [&](InteractionLoop& loop) {
			const auto visit = [&](const auto& functors) {
				for (const auto& functor : functors)
					if (auto* t = dynamic_cast<T*>(functor.get())) f(*t);
			};
			if constexpr (std::is_base_of<IGeomFunctor, T>::value) visit(loop.geomDispatcher->functors);
			else if constexpr (std::is_base_of<IPhysFunctor, T>::value)
				visit(loop.physDispatcher->functors);
			else
				visit(loop.lawDispatcher->functors);
		});
	}

	/// The first functor of type T in the scene's InteractionLoops (see forEachLoopFunctor), or nullptr.
	template <class T> T* findLoopFunctor(const Scene* scene)
	{
		T* found = nullptr;
		forEachLoopFunctor<T>(scene, [&](T& t) {
			if (!found) found = &t;
		});
		return found;
	}

} // namespace rdem
} // namespace yade
