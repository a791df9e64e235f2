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
}
