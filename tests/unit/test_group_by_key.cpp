/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/GroupByKey.hpp: the counting sort behind the per-body lists of RdemForceAssembler and
   RdemPoissonEngine. Integer results: compared exactly. */
#include <pkg/rdem/math/GroupByKey.hpp>

#include <gtest/gtest.h>

namespace {

namespace rdem = yade::rdem;

TEST(GroupByKey, GroupsStablyWithEmptyKeys)
{
	// keys of items 0..6; key 1 and key 4 have no item
	const std::vector<int> keys { 3, 0, 3, 2, 0, 5, 3 };
	std::vector<size_t>    first, order;
	rdem::groupByKey(keys, 6, first, order);
	EXPECT_EQ(first, (std::vector<size_t> { 0, 2, 2, 3, 6, 6, 7 }));
	EXPECT_EQ(order, (std::vector<size_t> { 1, 4, 3, 0, 2, 6, 5 })); // within a key, items in increasing order
}

TEST(GroupByKey, NoItems)
{
	std::vector<size_t> first { 9 }, order { 9 };
	rdem::groupByKey(std::vector<int>(), 3, first, order);
	EXPECT_EQ(first, (std::vector<size_t> { 0, 0, 0, 0 }));
	EXPECT_TRUE(order.empty());
}

} // namespace
