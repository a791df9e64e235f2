package jade.core.behaviours;

import jade.core.Agent;
import jade.util.leap.ArrayList;
import jade.util.leap.Collection;

/**
 * Runs its children in turn, interleaved; it ends when all have ended ({@link #WHEN_ALL}), when
 * one has ({@link #WHEN_ANY}), or when a given number have.
 */
public class ParallelBehaviour extends CompositeBehaviour {
    private static final long serialVersionUID = 1L;

    public static final int WHEN_ALL = 0;
    public static final int WHEN_ANY = 1;

    private final int whenToStop;
    private final ArrayList children = new ArrayList();
    private final ArrayList terminated = new ArrayList();
    private int index;

    public ParallelBehaviour() {
        this(WHEN_ALL);
    }

    public ParallelBehaviour(int endCondition) {
        this.whenToStop = endCondition;
    }

    public ParallelBehaviour(Agent a, int endCondition) {
        super(a);
        this.whenToStop = endCondition;
    }

    @Override
    protected void scheduleFirst() {
        index = 0;
        pickRunnable();
    }

    @Override
    protected void scheduleNext(boolean currentDone, int currentResult) {
        if (!currentDone) {
            index++;
        }
        pickRunnable();
    }

    @Override
    protected boolean checkTermination(boolean currentDone, int currentResult) {
        if (currentDone) {
            Behaviour b = (Behaviour) children.remove(index);
            terminated.add(b);
            // As JADE's round list: the turn goes back to the child before the one that ended, which runs next.
            int n = children.size();
            index = n == 0 ? 0 : (index - 1 + n) % n;
        }
        if (whenToStop == WHEN_ALL) {
            return children.isEmpty();
        }
        if (whenToStop == WHEN_ANY) {
            return terminated.size() >= 1 || children.isEmpty();
        }
        return terminated.size() >= whenToStop || children.isEmpty();
    }

    /** From the current index on, the first runnable child; the index stays if none is. */
    private void pickRunnable() {
        int n = children.size();
        if (n == 0) {
            index = 0;
            return;
        }
        index = index % n;
        for (int i = 0; i < n; i++) {
            int j = (index + i) % n;
            if (((Behaviour) children.get(j)).isRunnable()) {
                index = j;
                return;
            }
        }
    }

    @Override
    protected Behaviour getCurrent() {
        if (children.isEmpty()) {
            return null;
        }
        pickRunnable();
        return (Behaviour) children.get(index);
    }

    @Override
    public Collection getChildren() {
        return children;
    }

    /** The children that have ended. */
    public Collection getTerminatedChildren() {
        return terminated;
    }

    public void addSubBehaviour(Behaviour b) {
        children.add(b);
        registerAsChild(b);
    }

    public void removeSubBehaviour(Behaviour b) {
        children.remove(b);
        terminated.remove(b);
    }

    @Override
    public void reset() {
        for (Object o : terminated.toArray()) {
            children.add(o);
        }
        terminated.clear();
        super.reset();
        index = 0;
    }
}
