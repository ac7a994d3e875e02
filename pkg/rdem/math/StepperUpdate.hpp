/*************************************************************************
*  Copyright (C) 2026 yade-rdem authors                                  *
*                                                                        *
*  This program is free software; it is licensed under the terms of the  *
*  GNU General Public License v2 or later. See file LICENSE for details. *
*************************************************************************/
/* What an update of RdemTimeStepper does with its last estimate. K depends on the poses and on a "signature" of the
   springs (which exist, how stiff, which DOFs are free, how many broke: RdemTimeStepper::springSignature, its last
   entry the broken springs). While the signature is unchanged the estimate is kept (reuseUnchanged); a break changes
   only the dashpots (a broken segment keeps its spring as a contact spring), so after one the stiffest mode λ_K is
   kept and the dashpots' part is redone; anything else gets a fresh estimate, and at least one in every 100 updates. */
#pragma once

#include <algorithm>
#include <vector>

namespace yade {
namespace rdem {

	enum class StepperUpdate {
		Keep,     ///< the last estimate stands
		Dashpots, ///< λ_K and its Ritz vector kept, the dashpots and the damped limit redone
		Fresh     ///< a new estimate of both
	};

	struct StepperDecision {
		StepperUpdate what;
		bool          recordSignature; ///< whether the signature becomes the one the next updates compare with
	};

	/// Whether only the last entry (the broken springs) differs between two signatures of the same length.
	template <class S> bool onlyBreaksDiffer(const std::vector<S>& signature, const std::vector<S>& last)
	{
		return !signature.empty() && signature.size() == last.size() && std::equal(signature.begin(), signature.end() - 1, last.begin())
		        && signature.back() != last.back();
	}

	/* The decision of one update. young: the last fresh estimate is recent enough to keep (fewer than 99 kept since);
	   signature: the springs now (empty: no reuse, e.g. reuseUnchanged off); last: at the signature last recorded;
	   breakOnly: an update triggered by a break between two regular ones. An update for a break redoes the dashpots
	   even when other springs changed with it (contacts that came in the same step): those changes are then left to the
	   next regular update, so the signature is recorded only when nothing but the breaks differ, else the next regular
	   update would find it unchanged and keep λ_K without them. */
	template <class S> StepperDecision stepperDecision(bool young, const std::vector<S>& signature, const std::vector<S>& last, bool breakOnly)
	{
		if (!young || signature.empty()) return { StepperUpdate::Fresh, true };
		if (signature == last) return { StepperUpdate::Keep, false };
		const bool onlyBreaks = onlyBreaksDiffer(signature, last);
		if (breakOnly || onlyBreaks) return { StepperUpdate::Dashpots, onlyBreaks };
		return { StepperUpdate::Fresh, true };
	}

} // namespace rdem
} // namespace yade
