package io.concord.agents.control;

import io.concord.agents.proto.WheelchairMessage.Proposal;
import io.concord.core.acl.AclMessage;

import java.util.ArrayList;
import java.util.List;
import java.util.function.IntSupplier;

/**
 * The transports a control agent holds, in the order it got them, from the CFP to their end: those
 * it is evaluating or has proposed for, those accepted and queued, the one under way, and those
 * finished (kept for whoever reads {@link ControlAgent#tasks()}).
 */
final class TaskQueue {
    private final List<Task> tasks = new ArrayList<>();

    void add(Task t) {
        tasks.add(t);
    }

    void remove(Task t) {
        tasks.remove(t);
    }

    /** Every task, in order (a copy). */
    List<Task> all() {
        return new ArrayList<>(tasks);
    }

    /** The task of the contract-net conversation of {@code cfp}, or null. */
    Task ofCfp(AclMessage cfp) {
        for (Task t : tasks) {
            if (t.cfp.getConversationId() != null && t.cfp.getConversationId().equals(cfp.getConversationId())) {
                return t;
            }
        }
        return null;
    }

    /** The last accepted task of conversation {@code conversationId}, or null. */
    Task accepted(String conversationId) {
        Task found = null;
        for (Task t : tasks) {
            if (t.accept != null && conversationId != null && conversationId.equals(t.cfp.getConversationId())) {
                found = t;
            }
        }
        return found;
    }

    /** The first task accepted and not started, or null. */
    Task nextQueued() {
        for (Task t : tasks) {
            if (t.state == TaskView.State.QUEUED) {
                return t;
            }
        }
        return null;
    }

    /** How many tasks are accepted and not started. */
    int queued() {
        int n = 0;
        for (Task t : tasks) {
            if (t.state == TaskView.State.QUEUED) {
                n++;
            }
        }
        return n;
    }

    /** Whether the task is accepted and not finished (queued, or under way). */
    static boolean holds(Task t) {
        return t.state.compareTo(TaskView.State.QUEUED) >= 0 && t.state.compareTo(TaskView.State.UNLOADING) <= 0;
    }

    /** Whether any task is accepted and not finished. */
    boolean hasWork() {
        for (Task t : tasks) {
            if (holds(t)) {
                return true;
            }
        }
        return false;
    }

    /** The tasks accepted and not finished, in order. */
    List<Task> held() {
        return tasks.stream().filter(TaskQueue::holds).toList();
    }

    /** The node the queue ends at: the last accepted task's destination, or {@code chairAt}'s node. */
    int end(IntSupplier chairAt) {
        for (int i = tasks.size() - 1; i >= 0; i--) {
            Task t = tasks.get(i);
            if (t.toDropoff != null && holds(t)) {
                return t.to;
            }
        }
        return chairAt.getAsInt();
    }

    /**
     * Seconds of work ahead: the queued and running tasks, and those it has proposed for and not
     * heard back of (auctions run at once: a chair that counted only accepted work proposed the
     * same short cost for every one of them, and won them all while the other chairs stood).
     */
    double seconds() {
        double s = 0;
        for (Task t : tasks) {
            if (t.state == TaskView.State.PROPOSED || holds(t)) {
                s += t.estimateS;
            }
        }
        return s;
    }

    /** The proposals still open other than {@code t}'s, with their seconds. */
    List<Proposal.Pending> pendingBesides(Task t) {
        List<Proposal.Pending> pending = new ArrayList<>();
        for (Task o : tasks) {
            if (o != t && o.state == TaskView.State.PROPOSED) {
                pending.add(new Proposal.Pending(o.id, o.estimateS));
            }
        }
        return pending;
    }

    List<TaskView> views() {
        return tasks.stream().map(Task::view).toList();
    }
}
