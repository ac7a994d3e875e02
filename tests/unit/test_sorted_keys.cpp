// Unit tests of rdem::matchSortedKeys (pkg/rdem/math/SortedKeys.hpp) against a brute-force search.
#include <pkg/rdem/math/SortedKeys.hpp>
#include <algorithm>
#include <gtest/gtest.h>
#include <random>

using yade::rdem::matchSortedKeys;

namespace {
std::vector<int> randomAscending(std::mt19937& rng, int maxKey, double p)
{
	std::vector<int>            keys;
	std::bernoulli_distribution pick(p);
	for (int k = 0; k < maxKey; ++k)
		if (pick(rng)) keys.push_back(k);
	return keys;
}
}

TEST(SortedKeys, MatchesBruteForceOnRandomLists)
{
	std::mt19937 rng(7);
	for (int trial = 0; trial < 500; ++trial) {
		const auto       previous = randomAscending(rng, 109, 0.1 * (trial % 10));
		const auto       current  = randomAscending(rng, 109, 0.1 * ((trial / 10) % 10));
		std::vector<int> index(current.size(), -2);
		matchSortedKeys(previous, current.data(), current.size(), index.data());
		for (size_t k = 0; k < current.size(); ++k) {
			const auto it       = std::find(previous.begin(), previous.end(), current[k]);
			const int  expected = it == previous.end() ? -1 : int(it - previous.begin());
			ASSERT_EQ(index[k], expected) << "trial " << trial << ", key " << current[k];
		}
	}
}

TEST(SortedKeys, EmptyListsAndDisjointKeys)
{
	const std::vector<int> none, previous { 1, 3, 5 };
	const int              current[] = { 0, 2, 4, 6 };
	int                    index[4];
	matchSortedKeys(none, current, 4, index);
	for (int i : index)
		EXPECT_EQ(i, -1);
	matchSortedKeys(previous, current, 4, index);
	for (int i : index)
		EXPECT_EQ(i, -1);
	matchSortedKeys(previous, current, 0, index); // nothing to match: no write, no throw
}

TEST(SortedKeys, RefusesKeysOutOfOrder)
{
	const std::vector<int> previous { 1, 2 };
	const int              unordered[] = { 2, 1 };
	const int              repeated[]  = { 1, 1 };
	int                    index[2];
	EXPECT_THROW(matchSortedKeys(previous, unordered, 2, index), std::logic_error);
	EXPECT_THROW(matchSortedKeys(previous, repeated, 2, index), std::logic_error);
}
