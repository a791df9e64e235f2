package io.concord.agents.control;

import io.concord.agents.chair.ChairLayout;
import io.concord.agents.chair.ChairReadings;
import io.concord.agents.chair.ObstacleFilter;
import io.concord.agents.chair.Pose;
import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The obstacle filter alone, between a command and a chair that records what reaches it; the
 * readings are made by hand (their time is the chair's clock, set by each test).
 */
class ObstacleFilterTest {
    final Fakes.Chair chair = new Fakes.Chair();
    final ObstacleFilter filter = new ObstacleFilter(chair);
    static final Pose HERE = new Pose(0, 0, 0);

    private static ChairReadings ranges(long ms, double front, double irLeft, double irRight) {
        ChairReadings r = Fakes.reading(ms, HERE, front, 3.0);
        double[] ranges = new double[ChairLayout.standard().sensors().size()];
        for (int i = 0; i < ranges.length; i++) {
            ranges[i] = r.range(i);
        }
        ranges[ChairLayout.standard().sensorIndex("ir-front-left")] = irLeft;
        ranges[ChairLayout.standard().sensorIndex("ir-front-right")] = irRight;
        return new ChairReadings(r.timeNs(), r.seq(), 0, 0, ranges, false, 24, false, java.util.Set.of(), HERE, null);
    }

    @Test
    void aClearWayPassesTheCommandAsItIs() {
        filter.observe(ranges(0, 3.0, 0.8, 0.8));
        filter.drive(40, 38);
        assertEquals("drive 40,38", chair.last());
        assertTrue(Double.isNaN(filter.blockedAt()));
    }

    @Test
    void somethingNearAheadSlowsTheChairAndSomethingCloseStopsIt() {
        filter.observe(ranges(0, 1.0, 0.8, 0.8));
        filter.drive(40, 40);
        assertEquals(40 * ObstacleFilter.SLOW_SCALE, chair.lastPowers()[0], 1e-9, "slow zone: nearer than 1.2 m");
        filter.observe(ranges(50, 0.40, 0.8, 0.8));
        filter.drive(40, 40);
        assertEquals("stop", chair.last(), "stop zone: nearer than 0.45 m to the sonar");
        assertEquals(0.40, filter.blockedAt(), 1e-9);
        // Either infrared sensor stops it too, whatever the sonar says (a table's edge the sonar's cone misses).
        filter.observe(ranges(100, 3.0, 0.25, 0.8));
        filter.drive(40, 40);
        assertEquals("stop", chair.last());
        assertEquals(0.25, filter.blockedAt(), 1e-9);
        filter.observe(ranges(150, 3.0, 0.8, 0.29));
        filter.drive(40, 40);
        assertEquals("stop", chair.last());
        assertEquals(java.util.Map.of("obstacle-stop", 3L, "obstacle-slow", 1L), filter.counts());
    }

    @Test
    void aTurnOnTheSpotPassesSoThatTheChairCanTurnAway() {
        filter.observe(ranges(0, 0.2, 0.1, 0.1));
        filter.drive(-20, 20);
        assertEquals("drive -20,20", chair.last());
        assertTrue(Double.isNaN(filter.blockedAt()));
        // An arc is no turn on the spot: it moves forward, and is stopped.
        filter.drive(-10, 20);
        assertEquals("stop", chair.last());
    }

    @Test
    void theWayClearedTheCommandGoesThroughAgain() {
        filter.observe(ranges(0, 0.3, 0.8, 0.8));
        filter.drive(40, 40);
        filter.observe(ranges(50, 2.0, 0.8, 0.8));
        filter.drive(40, 40);
        assertEquals(List.of("stop", "drive 40,40"), chair.commands);
        assertTrue(Double.isNaN(filter.blockedAt()));
    }

    @Test
    void withoutAReadingOfItsOwnItJudgesOnTheChairsLatest() {
        chair.latest = ranges(0, 0.3, 0.8, 0.8);
        filter.drive(40, 40);
        assertEquals("stop", chair.last());
    }

    /** The defence off (a test's switch): the command reaches the chair whatever is ahead. */
    @Test
    void switchedOffItPassesEverything() {
        filter.enabled(false);
        filter.observe(ranges(0, 0.1, 0.1, 0.1));
        filter.drive(40, 40);
        assertEquals("drive 40,40", chair.last());
    }
}
