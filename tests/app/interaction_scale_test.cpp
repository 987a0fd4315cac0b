// The viewer's level of detail while the camera moves: the fraction of the render scale traced
// during a drag and shortly after a wheel click, the full render scale once the camera rests.
#include "app/viewer/interaction_scale.h"

#include <gtest/gtest.h>

using ivis::app::InteractionScale;

TEST(InteractionScale, TracesTheFullRenderScaleBeforeAnyMove)
{
    InteractionScale interaction;
    interaction.reduction = 0.5f;
    EXPECT_FALSE(interaction.moving(0.0));
    EXPECT_FLOAT_EQ(interaction.scale(0.5f, 0.0), 0.5f);
}

TEST(InteractionScale, StaysReducedForAWholeDragAndRestsAfterTheRelease)
{
    InteractionScale interaction;
    interaction.reduction = 0.5f;
    interaction.moved(10.0, true);
    EXPECT_FLOAT_EQ(interaction.scale(0.5f, 10.0), 0.25f);
    // A drag held still for seconds is still a drag: no full-size frame in the middle of it.
    EXPECT_FLOAT_EQ(interaction.scale(0.5f, 15.0), 0.25f);
    interaction.released();
    EXPECT_FLOAT_EQ(interaction.scale(0.5f, 15.0), 0.5f);
}

TEST(InteractionScale, RestsOnlyAfterTheRestTimeSinceTheLastMove)
{
    InteractionScale interaction;
    interaction.reduction = 0.25f;
    const double rest = InteractionScale::kRestSeconds;
    interaction.moved(2.0, false);  // a wheel click
    EXPECT_TRUE(interaction.moving(2.0 + 0.9 * rest));
    EXPECT_FLOAT_EQ(interaction.scale(1.0f, 2.0 + 0.9 * rest), 0.25f);
    EXPECT_FALSE(interaction.moving(2.0 + 1.1 * rest));
    EXPECT_FLOAT_EQ(interaction.scale(1.0f, 2.0 + 1.1 * rest), 1.0f);

    // A drag released right after its last move rests only when the rest time has passed too.
    interaction.moved(5.0, true);
    interaction.released();
    EXPECT_TRUE(interaction.moving(5.0 + 0.5 * rest));
    EXPECT_FALSE(interaction.moving(5.0 + 1.5 * rest));
}

TEST(InteractionScale, AReductionOfOneNeverLowersTheScale)
{
    InteractionScale interaction;
    interaction.reduction = 1.0f;
    interaction.moved(1.0, true);
    EXPECT_TRUE(interaction.moving(1.0));
    EXPECT_FLOAT_EQ(interaction.scale(0.75f, 1.0), 0.75f);
}

TEST(InteractionScale, AReleasedDragRestsAtOnceForAPictureAMoveCancels)
{
    InteractionScale interaction;
    const double rest = InteractionScale::kRestSeconds;
    interaction.moved(5.0, true);
    EXPECT_TRUE(interaction.movingBeforeCancellableRest(5.0));
    EXPECT_TRUE(interaction.movingBeforeCancellableRest(9.0));  // held still: still a drag
    interaction.released();
    EXPECT_FALSE(interaction.movingBeforeCancellableRest(5.0));
    EXPECT_TRUE(interaction.moving(5.0));  // a picture that blocks the window still waits the rest time

    // A wheel click has no release: it rests after the rest time, as moving() says.
    interaction.moved(6.0, false);
    EXPECT_TRUE(interaction.movingBeforeCancellableRest(6.0 + 0.5 * rest));
    EXPECT_FALSE(interaction.movingBeforeCancellableRest(6.0 + 1.5 * rest));
    // A release after a wheel click (every button up, each frame) does not end its rest time.
    interaction.released();
    interaction.moved(7.0, false);
    interaction.released();
    EXPECT_TRUE(interaction.movingBeforeCancellableRest(7.0 + 0.5 * rest));
}

TEST(InteractionScale, SaysWhenTheRestTimeEnds)
{
    InteractionScale interaction;
    const double rest = InteractionScale::kRestSeconds;
    EXPECT_EQ(interaction.secondsUntilRest(0.0), 0.0) << "never moved: resting";
    interaction.moved(2.0, false);  // a wheel click
    EXPECT_DOUBLE_EQ(interaction.secondsUntilRest(2.0), rest);
    EXPECT_NEAR(interaction.secondsUntilRest(2.0 + 0.25 * rest), 0.75 * rest, 1e-12);
    EXPECT_EQ(interaction.secondsUntilRest(2.0 + 2.0 * rest), 0.0);
    EXPECT_FALSE(interaction.moving(2.0 + rest + 1e-9)) << "moving() agrees once it is 0";
    interaction.moved(5.0, true);
    EXPECT_GT(interaction.secondsUntilRest(50.0), 0.0) << "a drag held still does not rest by the clock";
}
