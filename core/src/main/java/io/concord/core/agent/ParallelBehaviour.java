package io.concord.core.agent;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/**
 * Interleaves its children, one step of one runnable child per step of its own; done when all of
 * them ({@link #WHEN_ALL}), any of them ({@link #WHEN_ANY}), or a given number are done.
 */
public class ParallelBehaviour extends CompositeBehaviour {
    /** Done when every child is done. */
    public static final int WHEN_ALL = 0;
    /** Done when one child is done. */
    public static final int WHEN_ANY = 1;

    private final int condition;
    private final List<Behaviour> active = new ArrayList<>();
    private final List<Behaviour> all = new ArrayList<>();
    private int next;
    private int finished;

    /**
     * @param condition {@link #WHEN_ALL}, {@link #WHEN_ANY}, or a number of children that must finish
     */
    public ParallelBehaviour(Agent agent, int condition) {
        super(agent);
        if (condition < 0) {
            throw new IllegalArgumentException("condition must be WHEN_ALL, WHEN_ANY or a count > 0, got " + condition);
        }
        this.condition = condition;
    }

    public void addSubBehaviour(Behaviour b) {
        active.add(b);
        all.add(b);
        adopt(b);
    }

    @Override
    protected Collection<Behaviour> activeChildren() {
        return active;
    }

    @Override
    protected Collection<Behaviour> allChildren() {
        return all;
    }

    @Override
    public void action() {
        int n = active.size();
        for (int k = 0; k < n; k++) {
            int i = (next + k) % n;
            Behaviour c = active.get(i);
            if (!c.isRunnable()) {
                continue;
            }
            if (stepChild(c)) {
                c.onEnd();
                active.remove(i);
                finished++;
                next = active.isEmpty() ? 0 : i % active.size();
            } else {
                next = (i + 1) % n;
            }
            if (!done()) {
                blockIfNoChildRunnable();
            }
            return;
        }
        blockIfNoChildRunnable();
    }

    @Override
    public boolean done() {
        if (condition == WHEN_ALL) {
            return active.isEmpty();
        }
        return finished >= condition || active.isEmpty();
    }

    @Override
    public void reset() {
        super.reset();
        active.clear();
        active.addAll(all);
        next = 0;
        finished = 0;
    }
}
