package jade.core.behaviours;

import jade.core.Agent;
import jade.util.leap.ArrayList;
import jade.util.leap.Collection;

/** Runs its children one after the other; it ends after the last. */
public class SequentialBehaviour extends SerialBehaviour {
    private static final long serialVersionUID = 1L;

    private final ArrayList children = new ArrayList();
    private int index;

    public SequentialBehaviour() {
    }

    public SequentialBehaviour(Agent a) {
        super(a);
    }

    @Override
    protected void scheduleFirst() {
        index = 0;
    }

    @Override
    protected void scheduleNext(boolean currentDone, int currentResult) {
        if (currentDone) {
            index++;
        }
    }

    @Override
    protected boolean checkTermination(boolean currentDone, int currentResult) {
        return currentDone && index >= children.size() - 1;
    }

    @Override
    protected Behaviour getCurrent() {
        return index < children.size() ? (Behaviour) children.get(index) : null;
    }

    @Override
    public Collection getChildren() {
        return children;
    }

    /** Adds a child at the end. */
    public void addSubBehaviour(Behaviour b) {
        children.add(b);
        registerAsChild(b);
    }

    public void removeSubBehaviour(Behaviour b) {
        children.remove(b);
    }

    @Override
    public void reset() {
        super.reset();
        index = 0;
    }

    /** Skips the child after the current one. */
    public void skipNext() {
        index++;
    }
}
