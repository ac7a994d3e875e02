// Unit tests of rdem::matchSortedKeys (pkg/rdem/math/SortedKeys.hpp) against a brute-force search.
#include <pkg/rdem/math/SortedKeys.hpp>
#include <algorithm>
#include <gtest/gtest.h>
#include <random>

using yade::rdem::matchSortedKeys;
using yade::rdem::sumOfDropped;

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

/// value(j) of a list, as Ig2_RdemBlock_RdemBlock_RdemGeom computes a dropped sample's energy from its index.
auto at(const std::vector<double>& v)
{
	return [&v](size_t j) { return v.at(j); };
}

TEST(SortedKeys, SumOfDroppedAddsTheValuesOfTheKeysNotKept)
{
	// previous {1, 3, 5, 8} with values 1, 10, 100, 1000; current keeps 3 and 8 and adds 4 and 9: dropped 1 and 5.
	const std::vector<int>    previous { 1, 3, 5, 8 };
	const std::vector<double> value { 1, 10, 100, 1000 };
	const int                 current[] = { 3, 4, 8, 9 };
	EXPECT_EQ(sumOfDropped(previous, current, 4, at(value)), 101.0);
	EXPECT_EQ(sumOfDropped(previous, current, 0, at(value)), 1111.0); // nothing kept: all of it
	const std::vector<int>    none;
	const std::vector<double> noValue;
	EXPECT_EQ(sumOfDropped(none, current, 4, at(noValue)), 0.0);
	const int same[] = { 1, 3, 5, 8 };
	EXPECT_EQ(sumOfDropped(previous, same, 4, at(value)), 0.0);
	std::vector<size_t> asked; // value is asked for the dropped indices only
	sumOfDropped(previous, current, 4, [&](size_t j) {
		asked.push_back(j);
		return 0.0;
	});
	EXPECT_EQ(asked, (std::vector<size_t> { 0, 2 }));
}

TEST(SortedKeys, SumOfDroppedMatchesABruteForceSearch)
{
	std::mt19937 rng(7);
	for (int trial = 0; trial < 200; ++trial) {
		std::vector<int> previous, current;
		for (int key = 0; key < 60; ++key) {
			if (rng() % 3 == 0) previous.push_back(key);
			if (rng() % 3 == 0) current.push_back(key);
		}
		std::vector<double> value;
		for (size_t j = 0; j < previous.size(); ++j)
			value.push_back(double(rng() % 1000));
		double expected = 0;
		for (size_t j = 0; j < previous.size(); ++j)
			if (std::find(current.begin(), current.end(), previous[j]) == current.end()) expected += value[j];
		ASSERT_EQ(sumOfDropped(previous, current.data(), current.size(), at(value)), expected) << "trial " << trial;
	}
}

TEST(SortedKeys, SumOfDroppedRefusesKeysOutOfOrder)
{
	const std::vector<int>    previous { 1, 2 }, unordered { 2, 1 };
	const std::vector<double> value { 1, 2 };
	const int                 current[] = { 2, 1 };
	EXPECT_THROW(sumOfDropped(unordered, current, 0, at(value)), std::logic_error);
	EXPECT_THROW(sumOfDropped(previous, current, 2, at(value)), std::logic_error);
}
