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

	/// The sum of value(j) over the indices j of the keys previous[j] (strictly ascending) that are not among the `n` keys
	/// of `current` (strictly ascending): what the history of the last step held for the keys this step dropped (the
	/// elastic energy of the contact springs of samples that left the sampled set, Ig2_RdemBlock_RdemBlock_RdemGeom);
	/// value is called for those indices only. O(previous + current); throws std::logic_error as matchSortedKeys if a
	/// list is not strictly ascending.
	template <class Key, class Value>
	auto sumOfDropped(const std::vector<Key>& previous, const Key* current, size_t n, Value value) -> decltype(value(size_t(0)))
	{
		for (size_t k = 1; k < n; ++k)
			if (!(current[k - 1] < current[k])) throw std::logic_error("rdem::sumOfDropped: current keys are not strictly ascending");
		decltype(value(size_t(0))) sum = 0;
		size_t                     k   = 0;
		for (size_t j = 0; j < previous.size(); ++j) {
			if (j > 0 && !(previous[j - 1] < previous[j])) throw std::logic_error("rdem::sumOfDropped: previous keys are not strictly ascending");
			while (k < n && current[k] < previous[j])
				++k;
			if (!(k < n && current[k] == previous[j])) sum += value(j);
		}
		return sum;
	}

} // namespace rdem
} // namespace yade
