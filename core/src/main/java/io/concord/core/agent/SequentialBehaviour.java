package io.concord.core.agent;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

/** Runs its children one after the other; done when the last is done. */
public class SequentialBehaviour extends CompositeBehaviour {
    private final List<Behaviour> children = new ArrayList<>();
    private int current;

    public SequentialBehaviour() {
    }

    public SequentialBehaviour(Agent agent) {
        super(agent);
    }

    /** Appends a child. */
    public void addSubBehaviour(Behaviour b) {
        children.add(b);
        adopt(b);
    }

    @Override
    protected Collection<Behaviour> activeChildren() {
        return current < children.size() ? List.of(children.get(current)) : List.of();
    }

    @Override
    protected Collection<Behaviour> allChildren() {
        return children;
    }

    @Override
    public void action() {
        if (current >= children.size()) {
            return;
        }
        Behaviour c = children.get(current);
        if (stepChild(c)) {
            c.onEnd();
            current++;
        } else if (!c.isRunnable()) {
            block();
        }
    }

    @Override
    public boolean done() {
        return current >= children.size();
    }

    @Override
    public void reset() {
        super.reset();
        current = 0;
    }
}
