/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Matching two ascending key lists in one pass: the history of the contact samples of a pair of blocks is kept only for
   the samples that were in contact in the last step (a few of the 2·6·(n+1)²+1 possible keys), and this step's
   samples find their history by key. O(previous + current), no allocation. */
#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

namespace yade {
namespace rdem {

	/// For each of the `n` keys of `current` (strictly ascending), the index of the same key in `previous` (strictly
	/// ascending), or -1 if it is not there, written to index[0 … n-1]. Throws std::logic_error if `current` is not
	/// strictly ascending (the caller's sampling order changed: its history would be silently mismatched).
	template <class Key> void matchSortedKeys(const std::vector<Key>& previous, const Key* current, size_t n, int* index)
	{
		size_t j = 0;
		for (size_t k = 0; k < n; ++k) {
			if (k > 0 && !(current[k - 1] < current[k])) throw std::logic_error("rdem::matchSortedKeys: current keys are not strictly ascending");
			while (j < previous.size() && previous[j] < current[k])
				++j;
			index[k] = j < previous.size() && previous[j] == current[k] ? int(j) : -1;
		}
	}

} // namespace rdem
} // namespace yade
