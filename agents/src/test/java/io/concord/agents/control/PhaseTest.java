package io.concord.agents.control;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;
import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * Each phase of a transport alone, on a manual clock (the chair's, in ms): what the chair does in
 * it, what it says and reports, and which phase follows. {@link TaskRunner} only sequences them;
 * the scenario tests drive the whole.
 */
class PhaseTest {
    /** A context that records what the phases ask for. */
    private static final class Recorder implements Phase.Context {
        final List<List<Integer>> followed = new ArrayList<>();
        final List<String> said = new ArrayList<>();
        final List<TaskView.State> reported = new ArrayList<>();
        final List<String> finished = new ArrayList<>();

        @Override
        public void follow(List<Integer> nodes) {
            followed.add(nodes);
        }

        @Override
        public void say(String s) {
            said.add(s);
        }

        @Override
        public void progress(Task t) {
            reported.add(t.state);
        }

        @Override
        public void finish(Task t, String failure) {
            finished.add(t.id + ":" + failure);
        }

        @Override
        public void followBack(List<Integer> nodes) {
            followed.add(nodes);
        }

        final List<Integer> stood = new ArrayList<>();
        final List<String> replans = new ArrayList<>();

        @Override
        public void standAt(int node) {
            stood.add(node);
        }

        @Override
        public void clearRoute() {
        }

        @Override
        public Phase replan(Phase resume, int from, int goal, String why) {
            replans.add(from + "->" + goal);
            return new Replanning(resume, why);
        }
    }

    private static Task task() {
        Task t = new Task("T1", 3, 9, 3, 60, new AclMessage(Performative.CFP));
        t.toPickup = List.of(19, 18, 3);
        t.toDropoff = List.of(3, 4, 9);
        t.state = TaskView.State.QUEUED;
        return t;
    }

    @Test
    void toThePickUpTheChairDrivesAndAtItThePatientGetsOn() {
        Recorder c = new Recorder();
        Task t = task();
        Phase p = new ToPickup(t);
        assertEquals(TaskView.State.TO_PICKUP, t.state);
        assertTrue(p.drives(), "the chair drives to the patient");
        assertEquals(3, p.goal(), "its goal is the pick-up");
        assertSame(p, p.reading(5_000, c), "driving, a reading changes no phase");
        assertFalse(t.patientOnBoard());

        Phase next = p.arrived(10_000, c);
        assertInstanceOf(Loading.class, next);
        assertEquals(TaskView.State.LOADING, t.state);
        assertTrue(t.patientOnBoard(), "from the pick-up on, nobody else may take the patient");
        assertEquals(List.of("at node 3: the patient gets on (60 s)"), c.said);
        assertEquals(List.of(TaskView.State.LOADING), c.reported, "the giver is told at once");
    }

    @Test
    void loadingTheChairStandsForTheLoadingTimeThenDrivesToTheDropOff() {
        Recorder c = new Recorder();
        Task t = task();
        Phase p = new Loading(t, 10_000, c);
        assertFalse(p.drives(), "the chair stands while the patient gets on");
        assertEquals(9, p.goal(), "the patient on board, the goal is the drop-off");
        assertSame(p, p.reading(69_999, c), "60 s from 10 s: still loading at 69.999 s");
        assertTrue(c.followed.isEmpty());

        Phase next = p.reading(70_000, c);
        assertInstanceOf(ToDropoff.class, next);
        assertEquals(TaskView.State.TO_DROPOFF, t.state);
        assertTrue(next.drives());
        assertEquals(List.of(List.of(3, 4, 9)), c.followed, "it drives the planned way to the drop-off");
        assertEquals("drives T1 to node 9 by [3, 4, 9]", c.said.get(c.said.size() - 1));
        assertEquals(List.of(TaskView.State.LOADING, TaskView.State.TO_DROPOFF), c.reported);
    }

    @Test
    void atTheDropOffThePatientGetsOffAndThenTheTaskIsDone() {
        Recorder c = new Recorder();
        Task t = task();
        Phase p = new ToDropoff(t, c);
        Phase unloading = p.arrived(100_000, c);
        assertInstanceOf(Unloading.class, unloading);
        assertEquals(TaskView.State.UNLOADING, t.state);
        assertTrue(t.patientOnBoard(), "until the patient is off");
        assertFalse(unloading.drives());
        assertEquals("at node 9: the patient gets off (60 s)", c.said.get(c.said.size() - 1));

        assertSame(unloading, unloading.reading(159_999, c));
        assertTrue(c.finished.isEmpty(), "not done before the patient is off");
        assertNull(unloading.reading(160_000, c), "the last phase: the task has ended");
        assertEquals(List.of("T1:null"), c.finished, "done, with no failure");
    }

    @Test
    void aZeroLoadingTimeGoesOnAtTheNextReading() {
        Recorder c = new Recorder();
        Task t = new Task("T2", 3, 9, 0, 0, new AclMessage(Performative.CFP));
        t.toDropoff = List.of(3, 9);
        Phase p = new Loading(t, 10_000, c);
        assertInstanceOf(ToDropoff.class, p.reading(10_000, c));
    }

    @Test
    void aStepAsideStandsUntilItsWayIsPlannedDrivesItAndThenThePhaseGoesOnWhereItsGoalIs() {
        Recorder c = new Recorder();
        Task t = task();
        StepAside aside = new StepAside(new ToPickup(t), 3);
        assertEquals(TaskView.State.TO_PICKUP, t.state, "an interruption leaves the task's state as it was");
        assertSame(t, aside.task);
        assertEquals(3, aside.goal(), "the goal is still the interrupted phase's");
        assertTrue(aside.awaitsPlan());
        assertFalse(aside.drives(), "it stands until the way aside is planned");

        aside.planned(List.of(18, 3), c);
        assertTrue(aside.drives());
        assertEquals(List.of(List.of(18, 3)), c.followed);
        assertEquals("makes way for another chair: to node 3 by [18, 3]", c.said.get(0));

        Phase next = aside.arrived(20_000, c);
        assertInstanceOf(Loading.class, next, "it made way to the pick-up itself: the patient gets on");
        assertTrue(c.replans.isEmpty(), "nothing to plan");
    }

    @Test
    void aStepAsideEndingAwayFromTheGoalStandsThereAndReplansToIt() {
        Recorder c = new Recorder();
        Phase toPickup = new ToPickup(task());
        StepAside aside = new StepAside(toPickup, 17);
        aside.planned(List.of(18, 17), c);

        Phase next = aside.arrived(20_000, c);
        assertInstanceOf(Replanning.class, next);
        assertSame(toPickup, ((Replanning) next).resume, "then the way to the pick-up goes on");
        assertEquals(List.of(17), c.stood, "it holds the node it made way to while it waits");
        assertEquals(List.of("17->3"), c.replans);
        assertEquals("has made way at node 17", c.said.get(c.said.size() - 1));
    }

    @Test
    void anIdleChairGoesHomeAndIsIdleThere() {
        Recorder c = new Recorder();
        GoingHome home = new GoingHome(21);
        assertNull(home.task, "no task: it interrupts nothing");
        assertFalse(home.drives());
        home.planned(List.of(9, 20, 21), c);
        assertEquals("goes home: to parking place 21 by [9, 20, 21]", c.said.get(0));
        assertTrue(home.drives());
        assertNull(home.arrived(30_000, c), "parked: idle");
        assertTrue(c.replans.isEmpty());
        assertEquals("GoingHome(idle)", home.toString());
        // Out of another's way, to a node that is no parking place: it says so, not "home".
        Recorder aside = new Recorder();
        new GoingHome(5, false).planned(List.of(7, 4, 5), aside);
        assertEquals("makes way for another chair (it is idle): to node 5 by [7, 4, 5]", aside.said.get(0));
    }

    @Test
    void aReplanningStandsAndThenThePhaseGoesOnAlongTheNewPlanOrTheTaskFailsWithWhy() {
        Recorder c = new Recorder();
        Task t = task();
        Phase toDropoff = new ToDropoff(t, c);
        c.followed.clear();
        Replanning r = new Replanning(toDropoff, "door D1 did not open");
        assertFalse(r.drives(), "it stands until the plan comes");
        assertSame(r, r.reading(1_000, c));
        assertEquals(TaskView.State.TO_DROPOFF, t.state);

        assertSame(toDropoff, r.answered(List.of(4, 5, 9), null, c));
        assertEquals(List.of(List.of(4, 5, 9)), c.followed, "back to node 4, then on by the new plan");

        Replanning again = new Replanning(toDropoff, "door D2 did not open");
        assertNull(again.answered(null, "no route from 5 to 9", c));
        assertEquals(List.of("T1:no route from 5 to 9 (door D2 did not open)"), c.finished);
    }
}
