/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#include <pkg/rdem/RdemPhys.hpp>
#include <pkg/rdem/math/Failure.hpp>
#include <algorithm>

namespace yade {

YADE_PLUGIN((RdemPhys));

int RdemPhys::nIntact() const { return int(std::count(segState.begin(), segState.end(), int(rdem::SegmentState::Intact))); }

} // namespace yade
