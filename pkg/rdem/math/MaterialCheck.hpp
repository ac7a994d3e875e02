/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Validation of user-facing material parameters: each violated bound gives one message naming the parameter, its
   value and the allowed range, so that bad input is refused at set-up, never turned into NaN mid-run. */
#pragma once

#include <cmath>
#include <sstream>
#include <string>

namespace yade {
namespace rdem {

	template <class S> struct MaterialParameters {
		S young, poisson, density, tensileStrength, cohesion, frictionAngle, dampingNormal, dampingShear;
	};

	/// Empty string if all parameters are admissible, else one line per violated bound ("<owner>.<name> = <value>: ...").
	template <class S> std::string checkMaterial(const MaterialParameters<S>& m, const std::string& owner)
	{
		using std::isfinite;
		using std::isnan;
		std::ostringstream err;
		const S            pi = S(3.14159265358979323846);
		auto bad = [&](const char* name, S value, const char* range) { err << owner << "." << name << " = " << value << ": must be " << range << "\n"; };
		if (!(isfinite(m.young) && m.young > 0)) bad("young", m.young, "finite and > 0 [Pa]");
		if (!(m.poisson > -1 && m.poisson < S(0.5))) bad("poisson", m.poisson, "in (-1, 0.5)");
		if (!(isfinite(m.density) && m.density > 0)) bad("density", m.density, "finite and > 0 [kg/m3]");
		if (isnan(m.tensileStrength) || m.tensileStrength < 0) bad("tensileStrength", m.tensileStrength, ">= 0 [Pa] (inf: never breaks in tension)");
		if (isnan(m.cohesion) || m.cohesion < 0) bad("cohesion", m.cohesion, ">= 0 [Pa] (inf: never breaks in shear)");
		if (!(m.frictionAngle >= 0 && m.frictionAngle < pi / 2)) bad("frictionAngle", m.frictionAngle, "in [0, pi/2) [rad]");
		if (!(isfinite(m.dampingNormal) && m.dampingNormal >= 0)) bad("dampingNormal", m.dampingNormal, "finite and >= 0 (1 = critical)");
		if (!(isfinite(m.dampingShear) && m.dampingShear >= 0)) bad("dampingShear", m.dampingShear, "finite and >= 0 (1 = critical)");
		return err.str();
	}

	template <class S> struct JointParameters {
		S thickness, young, poisson, tensileStrength, cohesion, frictionAngle;
	};

	/// Empty string if all parameters of a mortar joint are admissible, else one line per violated bound.
	template <class S> std::string checkJoint(const JointParameters<S>& j, const std::string& owner)
	{
		using std::isfinite;
		using std::isnan;
		std::ostringstream err;
		const S            pi = S(3.14159265358979323846);
		auto bad = [&](const char* name, S value, const char* range) { err << owner << "." << name << " = " << value << ": must be " << range << "\n"; };
		if (!(isfinite(j.thickness) && j.thickness >= 0)) bad("thickness", j.thickness, "finite and >= 0 [m] (0: a bond interface without mortar)");
		if (!(isfinite(j.young) && j.young > 0)) bad("young", j.young, "finite and > 0 [Pa]");
		if (!(j.poisson > -1 && j.poisson < S(0.5))) bad("poisson", j.poisson, "in (-1, 0.5)");
		if (isnan(j.tensileStrength) || j.tensileStrength < 0) bad("tensileStrength", j.tensileStrength, ">= 0 [Pa] (inf: never breaks in tension)");
		if (isnan(j.cohesion) || j.cohesion < 0) bad("cohesion", j.cohesion, ">= 0 [Pa] (inf: never breaks in shear)");
		if (!(j.frictionAngle >= 0 && j.frictionAngle < pi / 2)) bad("frictionAngle", j.frictionAngle, "in [0, pi/2) [rad]");
		return err.str();
	}

} // namespace rdem
} // namespace yade
