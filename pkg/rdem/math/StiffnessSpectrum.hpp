/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* The largest eigenvalue of the mass-normalised linear stiffness A = P S K S P of a block assembly (doc/sphinx/rdemTheory.rst §6),
   for the critical time step 2/√λ_max of central differences (leapfrog). Plain arrays, Eigen only.

   Degrees of freedom: 6 per body, x = (u, θ) in global axes: translation u [m] and small rotation θ [rad] about the
   centroid. K [N/m, N, N·m/rad] is the tangent stiffness of the springs and Poisson terms at the current configuration
   without the geometric (stress) terms; S = diag(m^-½ I₃, R diag(I)^-½ Rᵀ) per body (m [kg], I the principal inertia
   [kg·m²] in body axes, R the body's rotation); P zeroes blocked DOFs. A [1/s²] is symmetric positive semi-definite.

   Sources of the parts:
   * a point spring of normal and shear stiffness k_n, k_s [N/m] between material points of two blocks (eq. 11-13 of the
     paper times the area): energy ½dᵀK_s d, K_s = k_n nnᵀ + k_s(I - nnᵀ), d = (u₂ + θ₂×r₂) - (u₁ + θ₁×r₁), r the arms;
   * a Poisson element (paper eq. 18-21): ½ s uᵀK_p u on the translations of its 8 nodes;
   * a Poisson cell (doc/sphinx/rdemTheory.rst §5.4): ½ εᵀK_c ε, ε_d = Σ_q c_q u_n,q, u_n = n·(u₂ + θ₂×r₂ - u₁ - θ₁×r₁) the opening
     of bond q at its face centre;
   * λ_max by the Lanczos method with full reorthogonalisation (Parlett 1998, ch. 13; Golub and Van Loan 2013, §10.1),
     reported as the largest Ritz value θ plus its residual norm β_k|s_k| (an eigenvalue lies within it of θ:
     Parlett 1998, Thm 4.5.1; the same a-posteriori upper estimate as Zhou and Li 2011). */
#pragma once

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <tuple>
#include <utility>
#include <vector>

namespace yade {
namespace rdem {

	/// Mass normalisation of one body (see the header): s_m = m^-½ [kg^-½], S_r = R diag(I)^-½ Rᵀ [kg^-½ m^-1], and which
	/// of its 6 global DOFs (x, y, z, rx, ry, rz) are free.
	template <class S> struct BodyScale {
		S                      invSqrtMass    = 0;
		Eigen::Matrix<S, 3, 3> invSqrtInertia = Eigen::Matrix<S, 3, 3>::Zero();
		std::array<bool, 6>    free {};
	};

	/// The mass normalisation of a body of mass m, principal inertia I (body axes), rotation R; blocked DOFs from YADE's
	/// bit mask (bit k: DOF k of x, y, z, rx, ry, rz blocked). A body without mass or inertia counts as fixed.
	template <class S> BodyScale<S> bodyScale(S m, const Eigen::Matrix<S, 3, 1>& I, const Eigen::Matrix<S, 3, 3>& R, unsigned blocked)
	{
		BodyScale<S> b;
		if (!(m > 0) || !(I.minCoeff() > 0)) return b;
		using std::sqrt;
		b.invSqrtMass    = 1 / sqrt(m);
		b.invSqrtInertia = R * I.cwiseSqrt().cwiseInverse().asDiagonal() * R.transpose();
		for (unsigned k = 0; k < 6; ++k)
			b.free[k] = !(blocked & (1u << k));
		return b;
	}

	/// The linear stiffness K of an assembly as 6×6 blocks: one diagonal block per body, one off-diagonal block per pair
	/// of bodies joined by springs, plus Poisson elements and cells kept in their own factorised form.
	template <class S> class BlockStiffness {
	public:
		using V3   = Eigen::Matrix<S, 3, 1>;
		using M3   = Eigen::Matrix<S, 3, 3>;
		using M6   = Eigen::Matrix<S, 6, 6>;
		using M24  = Eigen::Matrix<S, 24, 24>;
		using Link = std::pair<long, long>;

		explicit BlockStiffness(size_t nBodies)
		        : diag(nBodies, M6::Zero())
		{
		}

		size_t nBodies() const { return diag.size(); }

		/// Whether nothing nonzero was added (then K x = 0 for every x).
		bool empty() const { return !anyTerm; }

		/// The 6×6 diagonal block of body b from its point springs (pairs and fixed points; not the elements, openings,
		/// cells or offsets): for a sum of such springs K ⪯ 2 blockdiag(K_bb), as each pair's term is positive semi-definite.
		const M6& diagonalBlock(size_t b) const { return diag.at(b); }


		/// Opens the pair (b1, b2) for addPointSpring (b1 ≠ b2, both ≥ 0) until endPair; springs to a fixed point need none.
		void beginPair(long b1, long b2)
		{
			if (open.active) throw std::logic_error("BlockStiffness::beginPair: the pair opened last was not closed (endPair)");
			open        = OpenPair();
			open.b1     = b1;
			open.b2     = b2;
			open.active = true;
		}

		/* A point spring between body b1 (arm r1 from its centroid) and body b2 (arm r2) [m], unit normal n, stiffnesses
		   k_n, k_s [N/m]; b2 < 0: a spring to a fixed point. When b2 ≥ 0 it belongs to the pair opened by beginPair, whose
		   springs all sit at material points common to both bodies: r1 - r2 = d, one offset of the centroids per pair
		   (checked to round-off). Such a pair's terms are summed as moments of its arms and made 6×6 blocks once, by
		   endPair. */
		void addPointSpring(long b1, long b2, const V3& r1, const V3& r2, const V3& n, S kn, S ks)
		{
			if (kn == 0 && ks == 0) return;
			anyTerm = true;
			if (b2 < 0) {
				diag[size_t(b1)] += jtkj(kn * n * n.transpose() + ks * (M3::Identity() - n * n.transpose()), r1, r1);
				return;
			}
			if (!open.active || b1 != open.b1 || b2 != open.b2)
				throw std::logic_error("BlockStiffness::addPointSpring: the spring's bodies are not those of the open pair (beginPair)");
			const V3 d = r1 - r2;
			if (open.springs == 0) open.d = d;
			else if (!((d - open.d).norm() <= 1e-9 * (open.d.norm() + r1.norm())))
				throw std::logic_error("BlockStiffness::addPointSpring: the springs of a pair must sit at points common to both bodies (r1 - "
				                       "r2 the same for all)");
			open.springs += 1;
			open.moments.add(r1, n, kn, ks);
		}

		/// Closes the pair opened by beginPair: its summed terms go to the two diagonal blocks and the pair's block.
		void endPair()
		{
			if (!open.active) throw std::logic_error("BlockStiffness::endPair: no pair is open (beginPair)");
			open.active = false;
			if (open.springs == 0) return; // nothing added: no block for the pair
			/* M = Σ J(r1)ᵀK_s J(r1); with r2 = r1 - d, J(r2) = J(r1) T, T = [[I, [d]×], [0, I]], so that
			   Σ J(r1)ᵀK_s J(r2) = M T and Σ J(r2)ᵀK_s J(r2) = Tᵀ M T. */
			const M6 M = open.moments.block();
			const M3 D = cross(open.d);
			M6       MT; // M T, T = [[I, D], [0, I]]: by 3×3 blocks
			MT.template leftCols<3>()             = M.template leftCols<3>();
			MT.template topRightCorner<3, 3>()    = M.template topLeftCorner<3, 3>() * D + M.template topRightCorner<3, 3>();
			MT.template bottomRightCorner<3, 3>() = M.template bottomLeftCorner<3, 3>() * D + M.template bottomRightCorner<3, 3>();
			M6 TtMT                               = MT; // Tᵀ M T: Tᵀ = [[I, 0], [Dᵀ, I]]
			TtMT.template bottomRows<3>() += D.transpose() * MT.template topRows<3>();
			diag[size_t(open.b1)] += M;
			diag[size_t(open.b2)] += TtMT;
			pairs.push_back({ open.b1, open.b2 });
			offDiag.push_back(-MT);
		}

		/// A Poisson element: ½ s uᵀK u on the translations of its 8 nodes (body ids; K [N/m], not copied: it must outlive this).
		void addElement(const std::array<long, 8>& nodes, const M24* K, S s)
		{
			if (!(s > 0)) return;
			elements.push_back({ nodes, K, s });
			anyTerm = true;
		}

		/// A bond opening u_n = n·(u₂ - u₁) + a₂·θ₂ - a₁·θ₁ (a = r×n [m]) for addCell; returns its index.
		size_t addOpening(long b1, long b2, const V3& n, const V3& a1, const V3& a2)
		{
			openings.push_back({ b1, b2, n, a1, a2 });
			return openings.size() - 1;
		}

		/// A Poisson cell: ½ εᵀK ε [J] (K [N·m]), ε_d = Σ c u_n over its terms (opening index, axis d, c [1/m]); returns
		/// its index (for addOffsetShear).
		size_t addCell(const M3& K, const std::vector<std::tuple<size_t, int, S>>& terms)
		{
			cells.push_back({ K, terms });
			anyTerm = true;
			return cells.size() - 1;
		}

		/* The offset correction of a bond's intact shear springs (rdem::offsetSlip): springs of total shear stiffness
		   k [N/m] at the face centre (arms r1, r2 [m]) measure P(d - c), P = I - nnᵀ, d = P₂ - P₁ the relative
		   displacement of the face centre, c = A₁ε₁ - A₂ε₂ the slip of the two cells' strains ε (as addCell's terms
		   give them; cell < 0: a block without a cell) [m]. addPointSpring holds the springs' ½k|Pd|²; this adds the
		   rest of ½k|P(d - c)|², that is -k(Pd)·(Pc) + ½k|Pc|². */
		void addOffsetShear(long b1, long b2, const V3& r1, const V3& r2, const V3& n, S k, long cell1, const M3& A1, long cell2, const M3& A2)
		{
			if (k == 0 || (cell1 < 0 && cell2 < 0)) return;
			offsets.push_back({ b1, b2, r1, r2, n, k, cell1, cell2, A1, A2 });
			anyTerm = true;
		}

		/// y = K x (6 values per body) [N, N·m]; x and y of size 6·nBodies, y overwritten.
		void multiply(const S* x, S* y) const
		{
			if (open.active) throw std::logic_error("BlockStiffness::multiply: a pair is open (endPair)");
			using V6   = Eigen::Matrix<S, 6, 1>;
			using MV6  = Eigen::Map<V6>;
			using CMV6 = Eigen::Map<const V6>;
			for (size_t b = 0; b < diag.size(); ++b)
				MV6(y + 6 * b) = diag[b] * CMV6(x + 6 * b);
			for (size_t p = 0; p < pairs.size(); ++p) {
				const size_t i = size_t(pairs[p].first), j = size_t(pairs[p].second);
				MV6(y + 6 * i) += offDiag[p] * CMV6(x + 6 * j);
				MV6(y + 6 * j) += offDiag[p].transpose() * CMV6(x + 6 * i);
			}
			for (const auto& e : elements) {
				Eigen::Matrix<S, 24, 1> u;
				for (size_t a = 0; a < 8; ++a)
					u.template segment<3>(3 * long(a)) = Eigen::Map<const V3>(x + 6 * e.nodes[a]);
				const Eigen::Matrix<S, 24, 1> f = e.s * (*e.K * u);
				for (size_t a = 0; a < 8; ++a)
					Eigen::Map<V3>(y + 6 * e.nodes[a]) += f.template segment<3>(3 * long(a));
			}
			std::vector<S> un(openings.size());
			for (size_t q = 0; q < openings.size(); ++q)
				un[q] = openingOf(openings[q], x);
			std::vector<V3> eps(cells.size(), V3::Zero()), sigma(cells.size()); // per cell: ε and ∂W/∂ε
			for (size_t i = 0; i < cells.size(); ++i) {
				for (const auto& t : cells[i].terms)
					eps[i][std::get<1>(t)] += std::get<2>(t) * un[std::get<0>(t)];
				sigma[i] = cells[i].K * eps[i];
			}
			for (const auto& o : offsets) {
				const M3 P = M3::Identity() - o.n * o.n.transpose();
				V3       c = V3::Zero();
				if (o.cell1 >= 0) c += o.A1 * eps[size_t(o.cell1)];
				if (o.cell2 >= 0) c -= o.A2 * eps[size_t(o.cell2)];
				const V3 Pc = P * c, e = P * (pointDisplacement(x, o.b2, o.r2) - pointDisplacement(x, o.b1, o.r1)) - Pc;
				addPointForce(o.b2, o.r2, -o.k * Pc, y); // ∂/∂d of -k(Pd)·(Pc)
				addPointForce(o.b1, o.r1, o.k * Pc, y);
				if (o.cell1 >= 0) sigma[size_t(o.cell1)] -= o.k * (o.A1.transpose() * e); // ∂/∂c = -k P(d - c)
				if (o.cell2 >= 0) sigma[size_t(o.cell2)] += o.k * (o.A2.transpose() * e);
			}
			for (size_t i = 0; i < cells.size(); ++i)
				for (const auto& t : cells[i].terms)
					addOpeningForce(openings[std::get<0>(t)], std::get<2>(t) * sigma[i][std::get<1>(t)], y);
		}

		/// K as a dense matrix (for tests on small systems).
		Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> dense() const
		{
			const long                                       n = long(6 * diag.size());
			Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> K(n, n);
			Eigen::Matrix<S, Eigen::Dynamic, 1>              e = Eigen::Matrix<S, Eigen::Dynamic, 1>::Zero(n);
			for (long k = 0; k < n; ++k) {
				e.setZero();
				e[k] = 1;
				multiply(e.data(), K.col(k).data());
			}
			return K;
		}

	private:
		struct Element {
			std::array<long, 8> nodes;
			const M24*          K;
			S                   s;
		};
		struct Opening {
			long b1, b2;
			V3   n, a1, a2;
		};
		struct Cell {
			M3                                      K;
			std::vector<std::tuple<size_t, int, S>> terms;
		};
		struct OffsetShear {
			long b1, b2;
			V3   r1, r2, n;
			S    k;
			long cell1, cell2;
			M3   A1, A2;
		};
		/* The moments of the arms r of a pair's springs (K_s = k_s I + (k_n - k_s) nnᵀ), from which the 6×6 block
		   Σ J(r)ᵀK_s J(r) = [[Σ K_s, -Σ K_s[r]×], [Σ [r]×K_s, -Σ [r]×K_s[r]×]] is made once per pair:
		   K_s[r]× = [k_s r]× + (k_n - k_s) n (n×r)ᵀ and -[r]×K_s[r]× = k_s(|r|²I - r rᵀ) + (k_n - k_s)(r×n)(r×n)ᵀ. */
		struct ArmMoments {
			S  ks = 0, ksr2 = 0; // Σ k_s, Σ k_s |r|²
			V3 ksr = V3::Zero(); // Σ k_s r
			M3 dnn = M3::Zero(), ksrr = M3::Zero(), dnm = M3::Zero(),
			   dmm = M3::Zero(); // Σ δ nnᵀ, Σ k_s r rᵀ, Σ δ n mᵀ, Σ δ m mᵀ; δ = k_n - k_s, m = n×r
			void add(const V3& r, const V3& n, S kn, S kst)
			{
				const S  dk = kn - kst;
				const V3 m  = n.cross(r);
				ks += kst;
				ksr2 += kst * r.squaredNorm();
				ksr += kst * r;
				dnn += dk * n * n.transpose();
				ksrr += kst * r * r.transpose();
				dnm += dk * n * m.transpose();
				dmm += dk * m * m.transpose();
			}
			M6 block() const
			{
				const M3 KR = cross(ksr) + dnm; // Σ K_s[r]×
				M6       out;
				out.template topLeftCorner<3, 3>()     = ks * M3::Identity() + dnn;
				out.template topRightCorner<3, 3>()    = -KR;
				out.template bottomLeftCorner<3, 3>()  = -KR.transpose(); // Σ [r]×K_s = -(Σ K_s[r]×)ᵀ
				out.template bottomRightCorner<3, 3>() = ksr2 * M3::Identity() - ksrr + dmm;
				return out;
			}
		};
		/// The pair between beginPair and endPair.
		struct OpenPair {
			long       b1 = -1, b2 = -1;
			V3         d       = V3::Zero(); // r1 - r2 of its springs [m]
			long       springs = 0;
			ArmMoments moments;
			bool       active = false;
		};
		OpenPair                 open;
		std::vector<M6>          diag;
		std::vector<Link>        pairs;
		std::vector<M6>          offDiag;
		std::vector<Element>     elements;
		std::vector<Opening>     openings;
		std::vector<Cell>        cells;
		std::vector<OffsetShear> offsets;
		bool                     anyTerm = false;

		/// J_aᵀ K_s J_b, J = [I, -[r]×] the map from a body's (u, θ) to the displacement of the material point at arm r.
		static M6 jtkj(const M3& Ks, const V3& ra, const V3& rb)
		{
			const M3 Ra = cross(ra), Rb = cross(rb);
			M6       out;
			out.template topLeftCorner<3, 3>()     = Ks;
			out.template topRightCorner<3, 3>()    = -Ks * Rb;
			out.template bottomLeftCorner<3, 3>()  = Ra * Ks; // -[r_a]×ᵀ = [r_a]×
			out.template bottomRightCorner<3, 3>() = -Ra * Ks * Rb;
			return out;
		}
		static M3 cross(const V3& r)
		{
			M3 R;
			R << 0, -r[2], r[1], r[2], 0, -r[0], -r[1], r[0], 0;
			return R;
		}
		static S openingOf(const Opening& o, const S* x)
		{
			using CV3 = Eigen::Map<const V3>;
			return o.n.dot(CV3(x + 6 * o.b2) - CV3(x + 6 * o.b1)) + o.a2.dot(CV3(x + 6 * o.b2 + 3)) - o.a1.dot(CV3(x + 6 * o.b1 + 3));
		}
		/// The displacement u + θ×r of body b's material point at arm r, linearised.
		static V3 pointDisplacement(const S* x, long b, const V3& r)
		{
			using CV3 = Eigen::Map<const V3>;
			return CV3(x + 6 * b) + CV3(x + 6 * b + 3).cross(r);
		}
		/// Adds the generalised forces (F, r×F) of a force F at body b's material point at arm r to y.
		static void addPointForce(long b, const V3& r, const V3& F, S* y)
		{
			using MV3 = Eigen::Map<V3>;
			MV3(y + 6 * b) += F;
			MV3(y + 6 * b + 3) += r.cross(F);
		}
		/// Adds the generalised forces of a normal force F along the opening's gradient (∂u_n/∂x · F) to y.
		static void addOpeningForce(const Opening& o, S F, S* y)
		{
			using MV3 = Eigen::Map<V3>;
			MV3(y + 6 * o.b2) += F * o.n;
			MV3(y + 6 * o.b2 + 3) += F * o.a2;
			MV3(y + 6 * o.b1) -= F * o.n;
			MV3(y + 6 * o.b1 + 3) -= F * o.a1;
		}
	};

	/// x ← P S x per body (BodyScale): the mass normalisation, applied before and after K so that A = PSKSP [kg^-½].
	template <class S> void scaleDofs(const std::vector<BodyScale<S>>& scale, S* x)
	{
		using V3 = Eigen::Matrix<S, 3, 1>;
		for (size_t b = 0; b < scale.size(); ++b) {
			const BodyScale<S>& s = scale[b];
			V3                  u, t;
			for (int k = 0; k < 3; ++k) {
				u[k] = s.free[size_t(k)] ? x[6 * b + size_t(k)] : S(0);
				t[k] = s.free[size_t(k) + 3] ? x[6 * b + 3 + size_t(k)] : S(0);
			}
			t = s.invSqrtInertia * t;
			for (int k = 0; k < 3; ++k) {
				x[6 * b + size_t(k)]     = s.free[size_t(k)] ? s.invSqrtMass * u[k] : S(0);
				x[6 * b + 3 + size_t(k)] = s.free[size_t(k) + 3] ? t[k] : S(0);
			}
		}
	}

	/* The mass-normalised operators P S X S P of a block assembly on vectors of 6 values per body (scaleDofs), as the
	   time stepper's Lanczos runs multiply by them; one work vector for the scaled x. */
	template <class S> class NormalisedOperators {
	public:
		explicit NormalisedOperators(const std::vector<BodyScale<S>>& scale_)
		        : scale(scale_)
		        , w(6 * scale_.size())
		{
		}
		size_t size() const { return w.size(); }
		/// P as a Lanczos mask: 1 for a free DOF, 0 for a blocked one.
		std::vector<char> mask() const
		{
			std::vector<char> m(w.size(), 0);
			for (size_t b = 0; b < scale.size(); ++b)
				for (size_t k = 0; k < 6; ++k)
					m[6 * b + k] = scale[b].free[k];
			return m;
		}
		/// y = P S X S P x.
		void apply(const BlockStiffness<S>& X, const S* x, S* y)
		{
			scaled(x);
			X.multiply(w.data(), y);
			scaleDofs(scale, y);
		}
		/// kx = P S K S P x and cx = P S C S P x, with S P x made once for both.
		void applyBoth(const BlockStiffness<S>& K, const BlockStiffness<S>& C, const S* x, S* kx, S* cx)
		{
			scaled(x);
			K.multiply(w.data(), kx);
			scaleDofs(scale, kx);
			C.multiply(w.data(), cx);
			scaleDofs(scale, cx);
		}

	private:
		const std::vector<BodyScale<S>>& scale;
		std::vector<S>                   w;
		void                             scaled(const S* x)
		{
			w.assign(x, x + w.size());
			scaleDofs(scale, w.data());
		}
	};

	/// Result of lanczosLargest: the largest Ritz value θ [1/s²], its residual norm r (an eigenvalue of A lies in
	/// [θ - r, θ + r]), and the Lanczos steps taken.
	/// λ_max of S_b X S_b over body b's free DOFs, X a 6×6 symmetric block (diagonalBlock) in global axes, S_b its mass
	/// normalisation (bodyScale) [units of X over kg, e.g. 1/s for dashpots]; 0 for a fixed body.
	template <class S> S largestBlockEigenvalue(const Eigen::Matrix<S, 6, 6>& X, const BodyScale<S>& scale)
	{
		Eigen::Matrix<S, 6, 6> T = Eigen::Matrix<S, 6, 6>::Zero();
		T.template topLeftCorner<3, 3>().diagonal().setConstant(scale.invSqrtMass);
		T.template bottomRightCorner<3, 3>() = scale.invSqrtInertia;
		for (int k = 0; k < 6; ++k)
			if (!scale.free[size_t(k)]) T.col(k).setZero();
		const Eigen::Matrix<S, 6, 6> A = T.transpose() * X * T;
		return Eigen::SelfAdjointEigenSolver<Eigen::Matrix<S, 6, 6>>(A, Eigen::EigenvaluesOnly).eigenvalues().maxCoeff();
	}

	template <class S> struct LargestEigenvalue {
		S   ritz     = 0;
		S   residual = 0;
		int steps    = 0;
		/// θ + r, the estimate of λ_max used for the time step [1/s²].
		S upper() const { return ritz + residual; }
	};

	/// A deterministic start component in [-1, 1) for index i (splitmix64 hash): a generic vector with a component along
	/// every eigenvector, the same in every run.
	inline double startComponent(uint64_t i)
	{
		uint64_t z = (i + 1) * 0x9E3779B97F4A7C15ull;
		z          = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
		z          = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
		z ^= z >> 31;
		return double(z >> 11) / double(1ull << 52) - 1;
	}

	/* The largest eigenvalue of a symmetric positive semi-definite operator apply(x, y): y = A x on vectors of size n.
	   start: the warm start (the Ritz vector of an earlier call; empty or of another size: none), mixed with the generic
	   vector startComponent scaled to `mix` of its norm, so that modes absent from the old vector (a new contact) are
	   found too; on return it holds the new Ritz vector (unit). Iterates until r ≤ tol·θ after at least minSteps, at
	   most maxSteps (and n) steps. mask: per index, whether it is a free DOF (the start vector is zero elsewhere). */
	template <class S, class Apply>
	LargestEigenvalue<S>
	lanczosLargest(Apply&& apply, size_t n, const std::vector<char>& mask, std::vector<S>& start, int minSteps, int maxSteps, S tol, S mix)
	{
		using std::abs;
		using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1>;
		LargestEigenvalue<S> res;
		Vec                  v = Vec::Zero(long(n)), g = Vec::Zero(long(n));
		const bool           warm = start.size() == n && Eigen::Map<const Vec>(start.data(), long(n)).allFinite();
		for (size_t i = 0; i < n; ++i)
			if (mask[i]) g[long(i)] = S(startComponent(i));
		if (g.norm() == 0) return res; // no free DOF
		g /= g.norm();
		if (warm) {
			for (size_t i = 0; i < n; ++i)
				v[long(i)] = mask[i] ? start[i] : S(0);
			const S nv = v.norm();
			v          = nv > 0 ? Vec(v / nv + mix * g) : g;
		} else
			v = g;
		v /= v.norm();
		const int                                        kMax = int(std::min<size_t>(size_t(std::max(maxSteps, 1)), n));
		Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic> Q(long(n), kMax);
		std::vector<S>                                   alpha, beta;                    // the tridiagonal T_k
		Vec                                              w = Vec::Zero(long(n)), topVec; // T_k's eigenvector of θ
		int                                              k = 0;
		for (; k < kMax; ++k) {
			Q.col(k) = v;
			apply(v.data(), w.data());
			alpha.push_back(v.dot(w));
			// full reorthogonalisation, twice (Giraud et al.'s "twice is enough"), against round-off ghosts
			for (int pass = 0; pass < 2; ++pass)
				w -= Q.leftCols(k + 1) * (Q.leftCols(k + 1).transpose() * w);
			const S b = w.norm();
			// Ritz values of T_k
			Eigen::Matrix<S, Eigen::Dynamic, 1> d = Eigen::Map<Eigen::Matrix<S, Eigen::Dynamic, 1>>(alpha.data(), k + 1);
			Eigen::Matrix<S, Eigen::Dynamic, 1> e(std::max(k, 1));
			for (int i = 0; i < k; ++i)
				e[i] = beta[size_t(i)];
			Eigen::SelfAdjointEigenSolver<Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>> eig;
			eig.computeFromTridiagonal(d, e.head(k), Eigen::ComputeEigenvectors);
			const long top       = k; // eigenvalues ascending
			res.ritz             = eig.eigenvalues()[top];
			res.residual         = b * abs(eig.eigenvectors()(k, top));
			res.steps            = k + 1;
			topVec               = eig.eigenvectors().col(top);
			const bool converged = res.residual <= tol * res.ritz && k + 1 >= minSteps;
			if (converged || b <= S(1e-14) * std::max(res.ritz, S(1e-300))) break; // converged, or an invariant subspace
			beta.push_back(b);
			v = w / b;
		}
		const Vec ritzVec = Q.leftCols(std::min(k + 1, kMax)) * topVec; // the Ritz vector of the last step, made once
		start.assign(ritzVec.data(), ritzVec.data() + n);
		return res;
	}

	/* Critical time step of leapfrog (YADE's NewtonIntegrator) with dashpots that act on the mid-step velocity v_{n-1/2}
	   [s], from λ_K = λ_max(M^-½ K M^-½) [1/s²] and λ_C = λ_max(M^-½ C M^-½) [1/s] of the stiffness K and dashpot C
	   matrices (the same mass normalisation). The scheme v_{n+1/2} = v_{n-1/2} - Δt M⁻¹(K x_n + C v_{n-1/2}),
	   x_{n+1} = x_n + Δt v_{n+1/2} loses stability where its amplification has the eigenvalue -1 (x_{n+1} = -x_n), i.e. where
	   (Δt² K̃ + 2Δt C̃) x = 4x: Δt_crit solves λ_max(Δt² K̃ + 2Δt C̃) = 4. As λ_max(Δt² K̃ + 2Δt C̃) ≤ Δt² λ_K + 2Δt λ_C, the
	   root of Δt² λ_K + 2Δt λ_C = 4, Δt = 4/(λ_C + √(λ_C² + 4λ_K)), is a lower bound of it, exact when the stiffest and the
	   most damped mode are the same: for one oscillator (λ_K = ω², λ_C = 2ζω) it is (2/ω)(√(1+ζ²) - ζ) [Belytschko2000]_
	   §6.3, 0.414·2/ω for critical damping; without dashpots 2/ω. Infinite when both are zero. */
	template <class S> S dampedCriticalStep(S lambdaK, S lambdaC)
	{
		using std::sqrt;
		const S d = lambdaC + sqrt(lambdaC * lambdaC + 4 * lambdaK);
		return d > 0 ? 4 / d : std::numeric_limits<S>::infinity();
	}

	/// Result of dampedCriticalStepOf: the step [s] (a lower bound of the root, the value to use), an upper bound of the
	/// root [s], the rounds (Lanczos runs on Δt²K̃ + 2ΔtC̃) and their Lanczos steps in all.
	template <class S> struct DampedStep {
		S   step = 0, upper = 0;
		int rounds = 0, steps = 0;
	};

	/* The critical step of leapfrog with dashpots on the mid-step velocity, Δt_c solving λ_max(B(Δt)) = 4 with
	   B(Δt) = Δt²K̃ + 2ΔtC̃ (see dampedCriticalStep for the derivation; for K̃, C̃ symmetric positive semi-definite the
	   amplification's eigenvalues can leave the unit circle only through -1: on |z| = 1 the quadratic eigenproblem
	   (z - 2 + 1/z)x + Δt²K̃x + (1 - 1/z)ΔtC̃x = 0 has the imaginary part sin φ·Δt x*C̃x, zero only for z = ±1 or an
	   undamped x). applyK, applyC: y = K̃x, y = C̃x on vectors of size n; lambdaK, lambdaC their largest eigenvalues
	   (upper estimates) [1/s², 1/s]. f(Δt) = λ_max(B(Δt)) is increasing and convex, and for s ≥ 1 f(sΔt) ≤ s²f(Δt),
	   for s ≤ 1 f(sΔt) ≤ s f(Δt). So one Lanczos run at Δt with upper estimate μ of f(Δt) gives the lower bound
	   Δt·2/√μ (μ ≤ 4) or Δt·4/μ (μ > 4) of Δt_c; and its Ritz vector v, k = vᵀK̃v, c = vᵀC̃v, the upper bound
	   dampedCriticalStep(k, c) (vᵀB v ≤ f for every unit v), which is the next trial step (a Newton step of the convex f
	   on v's Rayleigh quotient: converges from above). Starts from dampedCriticalStep(lambdaK, lambdaC), the bound exact
	   when the stiffest and the most damped mode are one; stops when the bounds are within 2·tol (a Lanczos estimate
	   within tol of λ_max cannot bracket closer), once the lower bound reaches `enough` (a step the caller will not
	   exceed), or after maxRounds. start: warm start and new Ritz vector of B.
	   applyBoth(x, kx, cx): both products of one x (kx = K̃x, cx = C̃x; a caller may share work between them, such as the
	   mass normalisation of x); applyK(x, kx) alone. dampedCriticalStepOf below takes the two products apart. */
	template <class S, class ApplyBoth, class ApplyK>
	DampedStep<S> dampedCriticalStepOfBoth(
	        ApplyBoth&&              applyBoth,
	        ApplyK&&                 applyK,
	        size_t                   n,
	        const std::vector<char>& mask,
	        std::vector<S>&          start,
	        S                        lambdaK,
	        S                        lambdaC,
	        int                      maxSteps,
	        S                        tol,
	        int                      maxRounds,
	        S                        enough = std::numeric_limits<S>::infinity())
	{
		using std::sqrt;
		DampedStep<S> res;
		res.step  = dampedCriticalStep(lambdaK, lambdaC);
		res.upper = std::min(
		        lambdaK > 0 ? 2 / sqrt(lambdaK) : std::numeric_limits<S>::infinity(), lambdaC > 0 ? 2 / lambdaC : std::numeric_limits<S>::infinity());
		if (!(lambdaC > 0) || !(lambdaK > 0)) { // one of the two alone: the bound is the root
			res.upper = res.step;
			return res;
		}
		std::vector<S> kx(n), cx(n);
		S              dt    = res.step;
		const auto     apply = [&](const S* x, S* y) {
                        applyBoth(x, kx.data(), cx.data());
                        const S dt2 = dt * dt, twoDt = 2 * dt; // once, not per i (y could alias dt for the compiler)
                        for (size_t i = 0; i < n; ++i)
                                y[i] = dt2 * kx[i] + twoDt * cx[i];
		};
		while (res.rounds < maxRounds && res.step < (1 - 2 * tol) * res.upper && res.step < enough) {
			// the first round mixes in a generic vector (a new damped spot far from the old mode); later ones start from v
			const auto est = lanczosLargest<S>(apply, n, mask, start, 2, maxSteps, tol, S(res.rounds == 0 ? 0.1 : 0));
			res.rounds += 1;
			res.steps += est.steps;
			const S mu = est.upper();
			if (!(mu > 0)) break;
			res.step = std::max(res.step, mu > 4 ? dt * 4 / mu : dt * 2 / sqrt(mu));
			applyK(start.data(), kx.data()); // vᵀK̃v; vᵀC̃v from the Ritz value θ = vᵀBv = Δt²vᵀK̃v + 2Δt vᵀC̃v
			S k = 0;
			for (size_t i = 0; i < n; ++i)
				k += start[i] * kx[i];
			const S c = std::max(S(0), (est.ritz - dt * dt * k) / (2 * dt));
			res.upper = std::min(res.upper, dampedCriticalStep(k, c));
			dt        = std::max(res.upper, res.step); // the next trial: v's root (above Δt_c), not below what is proved
		}
		res.step = std::min(res.step, res.upper); // (a Lanczos run that missed the top mode could put it above)
		return res;
	}

	/// dampedCriticalStepOfBoth with the two products apart: applyK(x, y): y = K̃x, applyC(x, y): y = C̃x.
	template <class S, class ApplyK, class ApplyC>
	DampedStep<S> dampedCriticalStepOf(
	        ApplyK&&                 applyK,
	        ApplyC&&                 applyC,
	        size_t                   n,
	        const std::vector<char>& mask,
	        std::vector<S>&          start,
	        S                        lambdaK,
	        S                        lambdaC,
	        int                      maxSteps,
	        S                        tol,
	        int                      maxRounds,
	        S                        enough = std::numeric_limits<S>::infinity())
	{
		return dampedCriticalStepOfBoth<S>(
		        [&](const S* x, S* kx, S* cx) {
			        applyK(x, kx);
			        applyC(x, cx);
		        },
		        applyK,
		        n,
		        mask,
		        start,
		        lambdaK,
		        lambdaC,
		        maxSteps,
		        tol,
		        maxRounds,
		        enough);
	}

	/* Critical time step [s] once a critically damped dashpot (ζ = 1: eq. 13 with h = 1) acts on the stiffest mode, from
	   that mode's undamped limit 2/ω_max [s]: dampedCriticalStep(ω², 2ω) = (√2 − 1)·2/ω [Belytschko2000]_ §6.3, 0.414 of
	   it. The step that a contact forming before the next estimate allows (RdemTimeStepper.contactLimit). Infinite for an
	   infinite undamped limit (nothing elastic). */
	template <class S> S criticallyDampedStep(S undampedDt)
	{
		using std::isfinite;
		if (!isfinite(undampedDt)) return std::numeric_limits<S>::infinity();
		const S omega = 2 / undampedDt;
		return dampedCriticalStep(omega * omega, 2 * omega);
	}

} // namespace rdem
} // namespace yade
