/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Stable grouping of items by an integer key (counting sort), for per-body lists of interaction sides and of Poisson
   element nodes: O(items + keys), where one sort of all items would be O(items log items). */
#pragma once

#include <cstddef>
#include <vector>

namespace yade {
namespace rdem {

	/// Groups the items 0 … keys.size()-1 by their key (each in [0, nKeys)): afterwards the items of key b are
	/// order[first[b]], …, order[first[b+1] - 1], in increasing item order; first has nKeys + 1 entries.
	template <class Key> void groupByKey(const std::vector<Key>& keys, size_t nKeys, std::vector<size_t>& first, std::vector<size_t>& order)
	{
		first.assign(nKeys + 1, 0);
		for (const Key k : keys)
			++first[size_t(k) + 1];
		for (size_t b = 0; b < nKeys; ++b)
			first[b + 1] += first[b];
		order.assign(keys.size(), 0);
		std::vector<size_t> fill(first.begin(), first.end() - 1);
		for (size_t item = 0; item < keys.size(); ++item)
			order[fill[size_t(keys[item])]++] = item;
	}

} // namespace rdem
} // namespace yade
