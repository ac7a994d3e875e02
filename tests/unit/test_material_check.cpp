/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Unit tests of pkg/rdem/math/MaterialCheck.hpp: admissible parameters give no message; each inadmissible value
   gives exactly one line naming the owner, the parameter and "must be". Pure logic, no tolerances. */
#include <pkg/rdem/math/MaterialCheck.hpp>
#include <tests/unit/Scalar.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace {

using rdem_test::Scalar;

namespace rdem = yade::rdem;
using Params = rdem::MaterialParameters<Scalar>;

constexpr Scalar inf = std::numeric_limits<Scalar>::infinity();
constexpr Scalar nan = std::numeric_limits<Scalar>::quiet_NaN();

// Concrete: E = 30 GPa, ν = 0.2, ρ = 2400 kg/m³, f_t = 3 MPa, c = 6 MPa, φ = 0.6 rad, h_n = h_s = 1 (critical).
Params concrete() { return { 30e9, 0.2, 2400, 3e6, 6e6, 0.6, 1.0, 1.0 }; }

size_t countLines(const std::string& s)
{
	size_t n = 0;
	for (char ch : s)
		n += ch == '\n';
	return n;
}

TEST(MaterialCheck, ValidConcreteGivesNoMessage)
{
	EXPECT_EQ(rdem::checkMaterial(concrete(), "mat"), "");
	// Boundary values that are admissible: ν = 0 and ν just above -1 and below 0.5, φ = 0, f_t = c = 0, h = 0.
	Params p          = concrete();
	p.poisson         = 0;
	p.frictionAngle   = 0;
	p.tensileStrength = 0;
	p.cohesion        = 0;
	p.dampingNormal   = 0;
	p.dampingShear    = 0;
	EXPECT_EQ(rdem::checkMaterial(p, "mat"), "");
	p.poisson = 0.499;
	EXPECT_EQ(rdem::checkMaterial(p, "mat"), "");
	p.poisson = -0.999;
	EXPECT_EQ(rdem::checkMaterial(p, "mat"), "");
	p.frictionAngle = std::nextafter(M_PI / 2, 0.0);
	EXPECT_EQ(rdem::checkMaterial(p, "mat"), "");
}

TEST(MaterialCheck, InfiniteStrengthsAreValid)
{
	Params p          = concrete();
	p.tensileStrength = inf; // never breaks in tension
	EXPECT_EQ(rdem::checkMaterial(p, "mat"), "");
	p.cohesion = inf; // never breaks in shear either
	EXPECT_EQ(rdem::checkMaterial(p, "mat"), "");
}

struct BadCase {
	const char*                  name;  // parameter name expected in the message
	Scalar                       value; // offending value
	std::function<void(Params&)> set;
};

TEST(MaterialCheck, EachInvalidValueIsNamed)
{
	const auto setter = [](Scalar Params::*field, Scalar v) { return [field, v](Params& p) { p.*field = v; }; };
	const BadCase cases[] = {
		{ "young", 0, setter(&Params::young, 0) },
		{ "young", -1, setter(&Params::young, -1) },
		{ "young", inf, setter(&Params::young, inf) },
		{ "young", nan, setter(&Params::young, nan) },
		{ "poisson", 0.5, setter(&Params::poisson, 0.5) },
		{ "poisson", -1, setter(&Params::poisson, -1) },
		{ "poisson", 0.7, setter(&Params::poisson, 0.7) },
		{ "poisson", nan, setter(&Params::poisson, nan) },
		{ "density", 0, setter(&Params::density, 0) },
		{ "density", -2400, setter(&Params::density, -2400) },
		{ "density", inf, setter(&Params::density, inf) },
		{ "density", nan, setter(&Params::density, nan) },
		{ "tensileStrength", -1, setter(&Params::tensileStrength, -1) },
		{ "tensileStrength", -inf, setter(&Params::tensileStrength, -inf) },
		{ "tensileStrength", nan, setter(&Params::tensileStrength, nan) },
		{ "cohesion", -1, setter(&Params::cohesion, -1) },
		{ "cohesion", nan, setter(&Params::cohesion, nan) },
		{ "frictionAngle", -0.1, setter(&Params::frictionAngle, -0.1) },
		{ "frictionAngle", M_PI / 2, setter(&Params::frictionAngle, M_PI / 2) },
		{ "frictionAngle", 2.0, setter(&Params::frictionAngle, 2.0) },
		{ "frictionAngle", nan, setter(&Params::frictionAngle, nan) },
		{ "dampingNormal", -1, setter(&Params::dampingNormal, -1) },
		{ "dampingNormal", inf, setter(&Params::dampingNormal, inf) },
		{ "dampingNormal", nan, setter(&Params::dampingNormal, nan) },
		{ "dampingShear", -1, setter(&Params::dampingShear, -1) },
		{ "dampingShear", nan, setter(&Params::dampingShear, nan) },
	};
	for (const BadCase& bc : cases) {
		Params p = concrete();
		bc.set(p);
		const std::string msg = rdem::checkMaterial(p, "brick");
		SCOPED_TRACE(std::string(bc.name) + " = " + std::to_string(bc.value));
		EXPECT_NE(msg.find(std::string("brick.") + bc.name + " = "), std::string::npos) << msg;
		EXPECT_NE(msg.find("must be"), std::string::npos) << msg;
		EXPECT_EQ(countLines(msg), 1u) << msg; // only the offending parameter is reported
	}
}

TEST(MaterialCheck, SeveralViolationsGiveSeveralLines)
{
	Params p        = concrete();
	p.young         = -1;
	p.poisson       = 0.5;
	p.dampingNormal = -1;
	const std::string msg = rdem::checkMaterial(p, "m");
	EXPECT_EQ(countLines(msg), 3u) << msg;
	EXPECT_NE(msg.find("m.young = -1: must be"), std::string::npos) << msg;
	EXPECT_NE(msg.find("m.poisson = 0.5: must be in (-1, 0.5)"), std::string::npos) << msg;
	EXPECT_NE(msg.find("m.dampingNormal = -1: must be"), std::string::npos) << msg;
}

} // namespace
