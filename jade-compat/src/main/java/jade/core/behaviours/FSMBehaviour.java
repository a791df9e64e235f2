package jade.core.behaviours;

import jade.core.Agent;
import jade.util.leap.ArrayList;
import jade.util.leap.Collection;

import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;

/**
 * A finite state machine of behaviours: each state is a behaviour; when one ends, its
 * {@code onEnd()} value picks the transition to the next; it ends after a last state.
 */
public class FSMBehaviour extends SerialBehaviour {
    private static final long serialVersionUID = 1L;

    private final Map<String, Behaviour> states = new LinkedHashMap<>();
    private final Set<String> lastStates = new HashSet<>();
    private final Map<String, Map<Integer, Transition>> transitions = new HashMap<>();
    private final Map<String, Transition> defaults = new HashMap<>();
    private String firstName;
    /** The name of the state running now (protected, as JADE's). */
    protected String currentName;
    private int lastExitValue;

    private record Transition(String destination, String[] toBeReset) {
    }

    public FSMBehaviour() {
    }

    public FSMBehaviour(Agent a) {
        super(a);
    }

    /** Adds a state; the state's behaviour takes the state's name, as in JADE. */
    public void registerState(Behaviour state, String name) {
        state.setBehaviourName(name);
        states.put(name, state);
        registerAsChild(state);
    }

    public void registerFirstState(Behaviour state, String name) {
        registerState(state, name);
        firstName = name;
    }

    public void registerLastState(Behaviour state, String name) {
        registerState(state, name);
        lastStates.add(name);
    }

    public Behaviour deregisterState(String name) {
        lastStates.remove(name);
        transitions.remove(name);
        defaults.remove(name);
        return states.remove(name);
    }

    public void registerTransition(String source, String destination, int event) {
        registerTransition(source, destination, event, null);
    }

    /** A transition that also resets the named states when taken. */
    public void registerTransition(String source, String destination, int event, String[] toBeReset) {
        transitions.computeIfAbsent(source, k -> new HashMap<>()).put(event, new Transition(destination, toBeReset));
    }

    public void registerDefaultTransition(String source, String destination) {
        registerDefaultTransition(source, destination, null);
    }

    public void registerDefaultTransition(String source, String destination, String[] toBeReset) {
        defaults.put(source, new Transition(destination, toBeReset));
    }

    public void deregisterTransition(String source, int event) {
        Map<Integer, Transition> t = transitions.get(source);
        if (t != null) {
            t.remove(event);
        }
    }

    public void deregisterDefaultTransition(String source) {
        defaults.remove(source);
    }

    public boolean hasDefaultTransition(String source) {
        return defaults.containsKey(source);
    }

    public Behaviour getState(String name) {
        return states.get(name);
    }

    /** The name a state was registered with, or null. */
    public String getName(Behaviour state) {
        for (Map.Entry<String, Behaviour> e : states.entrySet()) {
            if (e.getValue() == state) {
                return e.getKey();
            }
        }
        return null;
    }

    /** The exit value of the last state that ended. */
    public int getLastExitValue() {
        return lastExitValue;
    }

    /** The exit value of the last state. */
    @Override
    public int onEnd() {
        return lastExitValue;
    }

    @Override
    protected void scheduleFirst() {
        currentName = firstName;
    }

    @Override
    protected void scheduleNext(boolean currentDone, int currentResult) {
        if (!currentDone) {
            return;
        }
        Map<Integer, Transition> byEvent = transitions.get(currentName);
        Transition t = byEvent == null ? null : byEvent.get(currentResult);
        if (t == null) {
            t = defaults.get(currentName);
        }
        if (t == null) {
            throw new IllegalStateException("Inconsistent FSM. State: " + currentName + " event: " + currentResult);
        }
        if (t.toBeReset() != null) {
            resetStates(t.toBeReset());
        }
        currentName = t.destination();
    }

    @Override
    protected boolean checkTermination(boolean currentDone, int currentResult) {
        if (currentDone) {
            lastExitValue = currentResult;
            return lastStates.contains(currentName);
        }
        return false;
    }

    @Override
    protected Behaviour getCurrent() {
        return currentName == null ? null : states.get(currentName);
    }

    @Override
    public Collection getChildren() {
        ArrayList l = new ArrayList();
        for (Behaviour b : states.values()) {
            l.add(b);
        }
        return l;
    }

    @Override
    public void reset() {
        super.reset();
        currentName = firstName;
    }

    /** Resets the named states. */
    public void resetStates(String[] names) {
        for (String n : names) {
            Behaviour b = states.get(n);
            if (b != null) {
                b.reset();
            }
        }
    }

    /** The transitions, one a line. */
    public String stringifyTransitionTable() {
        StringBuilder b = new StringBuilder();
        for (Map.Entry<String, Map<Integer, Transition>> e : transitions.entrySet()) {
            for (Map.Entry<Integer, Transition> t : e.getValue().entrySet()) {
                b.append("SRC=").append(e.getKey()).append(" DEST=").append(t.getValue().destination())
                        .append(" EVENT=").append(t.getKey()).append('\n');
            }
        }
        for (Map.Entry<String, Transition> e : defaults.entrySet()) {
            b.append("SRC=").append(e.getKey()).append(" DEST=").append(e.getValue().destination()).append(" DEFAULT\n");
        }
        return b.toString();
    }
}
