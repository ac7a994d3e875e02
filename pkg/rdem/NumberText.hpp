/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
#pragma once

#include <iomanip>
#include <sstream>
#include <string>

namespace yade {
namespace rdem {
	/// A number in a message, as std::to_string writes a double ("%f": six decimals), for any Real of YADE's builds
	/// (std::to_string takes built-in types only; YADE's Real is a class in its long-double, float128 and MPFR builds).
	template <class T> std::string numberText(const T& x)
	{
		std::ostringstream out;
		out << std::fixed << std::setprecision(6) << x;
		return out.str();
	}
} // namespace rdem
} // namespace yade
