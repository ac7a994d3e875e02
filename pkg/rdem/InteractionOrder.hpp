/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <core/Scene.hpp>
#include <pkg/rdem/RdemGeom.hpp>
#include <pkg/rdem/RdemPhys.hpp>
#include <algorithm>
#include <cstdint>
#include <utility>

namespace yade {
namespace rdem {

	/* The real interactions of the plugin (RdemGeom and RdemPhys) in the order of their bodies' ids. Sums over them do
	   not depend on the order of the interaction container, which O.load (interactions without geometry are not saved
	   and come back at its end) and the collider change: a reloaded run then takes the same time steps to the last bit. */
	inline vector<const Interaction*> interactionsInIdOrder(const Scene* scene)
	{
		// sorted by the key (id1, id2) as one 64-bit number (ids ≥ 0, one interaction per pair: no ties), which the sort
		// compares without reading the interactions again
		vector<std::pair<uint64_t, const Interaction*>> keyed;
		for (const auto& I : *scene->interactions)
			if (I->isReal() && dynamic_cast<const RdemGeom*>(I->geom.get()) && dynamic_cast<const RdemPhys*>(I->phys.get()))
				keyed.emplace_back(uint64_t(uint32_t(I->getId1())) << 32 | uint64_t(uint32_t(I->getId2())), I.get());
		std::sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
		vector<const Interaction*> out(keyed.size());
		for (size_t i = 0; i < keyed.size(); ++i)
			out[i] = keyed[i].second;
		return out;
	}

} // namespace rdem
} // namespace yade
