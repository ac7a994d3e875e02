/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* Isotropic linear elasticity and the spring constants of the refined DEM.

   Pure functions, Eigen only, templated on the scalar so that they are unit-tested in double
   without YADE and used with yade::Real inside the plugin.

   Reference [P]: "Incorporating Poisson effect into DEM for enhanced numerical analysis of masonry
   structures" (shared/reference/paper-poisson-effect-refined-dem.txt), equations (11)-(13), (18), (19).
   Units: SI throughout (Pa, m, kg, s). Voigt order (xx, yy, zz, yz, zx, xy), engineering shear strains. */
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <string>

namespace yade {
namespace rdem {

	template <class S> using Matrix6 = Eigen::Matrix<S, 6, 6>;

	/* Normal stiffness modulus of the face springs.
	   Paper:      E/(1-ν²), the plane-stress modulus of eq. (8) used by eq. (11) [P].
	   Consistent: λ+2μ = E(1-ν)/((1+ν)(1-2ν)), the diagonal of eq. (18), so that springs (diagonal)
	               plus Poisson elements (off-diagonal, eq. 19) add up to the full isotropic tensor
	               (derivation: doc/sphinx/rdemTheory.rst §5.2). */
	enum class SpringModulus { Paper = 0, Consistent = 1 };

	/// The formulation named "paper" or "consistent"; false if the name is neither.
	inline bool springModulusFromName(const std::string& name, SpringModulus& m)
	{
		if (name == "paper") m = SpringModulus::Paper;
		else if (name == "consistent")
			m = SpringModulus::Consistent;
		else
			return false;
		return true;
	}

	/// Lamé's first parameter λ = Eν/((1+ν)(1-2ν)) [Pa]; equals the off-diagonal entry of eq. (18).
	template <class S> S lameLambda(S E, S nu) { return E * nu / ((1 + nu) * (1 - 2 * nu)); }

	/// Shear modulus μ = G = E/(2(1+ν)) [Pa].
	template <class S> S shearModulus(S E, S nu) { return E / (2 * (1 + nu)); }

	/* Lamé λ of a Poisson element whose nodes are blocks of different materials [Pa]: the coupling of a finely layered
	   medium across its layers, λ_e = <λ/M>/<1/M> with M = λ+2μ and <·> volume averages (Backus 1962, "Long-wave elastic
	   anisotropy produced by horizontal layering", J. Geophys. Res. 67(11):4427-4440: the C13 of the layered medium).
	   One material: λ. Equal ν: the volume-weighted harmonic mean of λ, so a soft layer (mortar) softens the coupling as it
	   softens the series springs (eq. 12); the arithmetic mean would pair a stiff λ with soft springs, an indefinite
	   element. parts: (volume [m³], E [Pa], ν) of each block. */
	template <class S, class Parts> S layeredLambda(const Parts& parts)
	{
		S lambdaOverM = 0, complianceM = 0;
		for (const auto& p : parts) {
			const S lam = lameLambda(p[1], p[2]), M = lam + 2 * shearModulus(p[1], p[2]);
			lambdaOverM += p[0] * lam / M;
			complianceM += p[0] / M;
		}
		return lambdaOverM / complianceM;
	}

	/// Normal modulus of a face spring [Pa], see SpringModulus.
	template <class S> S springNormalModulus(S E, S nu, SpringModulus m)
	{
		return m == SpringModulus::Paper ? E / (1 - nu * nu) : lameLambda(E, nu) + 2 * shearModulus(E, nu);
	}

	/// Eq. (11) [P], normal: stiffness per unit area of the pyramid between a face and the centroid at distance ℓ [N/m³].
	template <class S> S normalStiffnessPerArea(S E, S nu, S ell, SpringModulus m) { return springNormalModulus(E, nu, m) / ell; }

	/// Eq. (11) [P], shear: k_s = E/(2(1+ν)ℓ) [N/m³].
	template <class S> S shearStiffnessPerArea(S E, S nu, S ell) { return shearModulus(E, nu) / ell; }

	/// Eq. (12) [P]: the springs of blocks A and B in series, k̄ = 1/(1/k_A + 1/k_B) [N/m³].
	template <class S> S seriesStiffness(S kA, S kB) { return 1 / (1 / kA + 1 / kB); }

	/* Compliance per area of one block's side of a bond [m³/N]: from the block's centroid to the joint's mid-plane at
	   distance ℓ, the block's material over ℓ - t/2 and the mortar over t/2 (eq. 12 [P] extended by the mortar term of a
	   joint of thickness t; doc/sphinx/rdemTheory.rst §1.1). modulusBlock and modulusMortar are both normal (M) or both shear (G)
	   moduli [Pa]. t = 0: ℓ/M, the inverse of eq. (11). The bond's stiffness per area is 1/(C_A + C_B). */
	template <class S> S bondSideCompliance(S modulusBlock, S ell, S modulusMortar, S thickness)
	{
		return (ell - thickness / 2) / modulusBlock + (thickness > 0 ? thickness / 2 / modulusMortar : S(0));
	}

	/// Eq. (13) [P]: equivalent mass per unit contact area m_ave = ρ_A ℓ_A + ρ_B ℓ_B [kg/m²].
	template <class S> S equivalentMassPerArea(S rhoA, S ellA, S rhoB, S ellB) { return rhoA * ellA + rhoB * ellB; }

	/// Eq. (13) [P]: dashpot coefficient per unit area c = 2h√(m_ave k) [N·s/m³]; h = 1 is critical damping.
	template <class S> S dampingPerArea(S h, S massPerArea, S kPerArea)
	{
		using std::sqrt;
		return 2 * h * sqrt(massPerArea * kPerArea);
	}

	/// Eq. (18) [P]: isotropic elasticity tensor D in Voigt notation, σ = D ε.
	template <class S> Matrix6<S> elasticityTensor(S E, S nu)
	{
		const S    lambda = lameLambda(E, nu), mu = shearModulus(E, nu);
		Matrix6<S> D      = Matrix6<S>::Zero();
		D.template topLeftCorner<3, 3>().setConstant(lambda);
		for (int i = 0; i < 3; ++i) {
			D(i, i)         = lambda + 2 * mu;
			D(i + 3, i + 3) = mu;
		}
		return D;
	}

	/// Eq. (19) [P] from λ directly: D_p has λ between different normal components and zeros elsewhere.
	template <class S> Matrix6<S> poissonTensorFromLambda(S lambda)
	{
		Matrix6<S> Dp = Matrix6<S>::Zero();
		Dp.template topLeftCorner<3, 3>().setConstant(lambda);
		for (int i = 0; i < 3; ++i)
			Dp(i, i) = 0;
		return Dp;
	}

	/// Eq. (19) [P]: the off-diagonal (Poisson) part D_p of eq. (18).
	template <class S> Matrix6<S> poissonTensor(S E, S nu) { return poissonTensorFromLambda(lameLambda(E, nu)); }

} // namespace rdem
} // namespace yade
