// Unit tests of rdem::stepperDecision (pkg/rdem/math/StepperUpdate.hpp): what an update of RdemTimeStepper does with
// its last estimate, case by case, and a sequence of updates in which a break comes with a new contact.
#include <pkg/rdem/math/StepperUpdate.hpp>
#include <gtest/gtest.h>

using yade::rdem::stepperDecision;
using yade::rdem::StepperUpdate;

namespace {
// signature: bodies, interactions, segments, samples, stiffness, blocked, mass, broken springs (the last)
const std::vector<double> base { 10, 20, 80, 4, 1.5e9, 0, 12.5, 3 };
std::vector<double>       with(size_t i, double v)
{
	auto s = base;
	s[i]   = v;
	return s;
}
}

TEST(StepperUpdate, CaseByCase)
{
	const auto broke = with(7, 4), contact = with(3, 9), brokeAndContact = with(3, 9);
	auto       both = brokeAndContact;
	both[7]         = 4;
	// unchanged: kept, also when a break triggered the update (the break was already taken)
	EXPECT_EQ(stepperDecision(true, base, base, false).what, StepperUpdate::Keep);
	EXPECT_EQ(stepperDecision(true, base, base, true).what, StepperUpdate::Keep);
	EXPECT_FALSE(stepperDecision(true, base, base, false).recordSignature);
	// only breaks: the dashpots, at a regular update or one for the break, and the signature recorded
	for (bool breakOnly : { false, true }) {
		const auto d = stepperDecision(true, broke, base, breakOnly);
		EXPECT_EQ(d.what, StepperUpdate::Dashpots);
		EXPECT_TRUE(d.recordSignature);
	}
	// a break with a new contact, at an update for the break: the dashpots, the signature not recorded
	const auto d = stepperDecision(true, both, base, true);
	EXPECT_EQ(d.what, StepperUpdate::Dashpots);
	EXPECT_FALSE(d.recordSignature);
	// the same at a regular update, and a new contact alone: fresh
	EXPECT_EQ(stepperDecision(true, both, base, false).what, StepperUpdate::Fresh);
	EXPECT_EQ(stepperDecision(true, contact, base, false).what, StepperUpdate::Fresh);
	// old estimate, no signature (reuseUnchanged off), or a signature of another length: fresh, recorded
	for (const auto& d2 : { stepperDecision(false, base, base, false),
	                        stepperDecision(true, std::vector<double>(), base, false),
	                        stepperDecision(true, broke, std::vector<double>(base.begin(), base.end() - 1), false) }) {
		EXPECT_EQ(d2.what, StepperUpdate::Fresh);
		EXPECT_TRUE(d2.recordSignature);
	}
}

TEST(StepperUpdate, ContactThatCameWithABreakReachesTheNextRegularUpdate)
{
	// Updates as RdemTimeStepper makes them: a regular one records base; a break comes with a new contact (update for
	// the break); nothing changes until the next regular update, which must estimate afresh (before the fix, the
	// update for the break recorded the signature and the regular one kept lambda_K without the contact).
	std::vector<double> last = base;
	auto                now  = with(3, 9);
	now[7]                   = 4;
	auto forBreak            = stepperDecision(true, now, last, true);
	if (forBreak.recordSignature) last = now;
	EXPECT_EQ(forBreak.what, StepperUpdate::Dashpots);
	const auto regular = stepperDecision(true, now, last, false);
	EXPECT_EQ(regular.what, StepperUpdate::Fresh);
	EXPECT_TRUE(regular.recordSignature);
	last = now;
	EXPECT_EQ(stepperDecision(true, now, last, false).what, StepperUpdate::Keep); // and then kept
}
