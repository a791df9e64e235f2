package io.concord.core.agent;

import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A finite state machine whose states are behaviours. When a state's behaviour is done, its
 * {@code onEnd()} value picks the transition; reaching a last state ends the machine, whose exit
 * value is that state's. As in JADE, a state entered again is not reset unless the transition
 * names it in {@code toBeReset}.
 */
public class FSMBehaviour extends CompositeBehaviour {
    private final Map<String, Behaviour> states = new LinkedHashMap<>();
    private final Map<Behaviour, String> names = new HashMap<>();
    private final Set<String> lastStates = new HashSet<>();
    private final Map<String, Map<Integer, Transition>> transitions = new HashMap<>();
    private final Map<String, Transition> defaults = new HashMap<>();
    private String first;
    private String currentName;
    private Behaviour current;
    private boolean finished;
    private int lastExitValue;

    private record Transition(String to, String[] toBeReset) {
    }

    public FSMBehaviour() {
    }

    public FSMBehaviour(Agent agent) {
        super(agent);
    }

    public void registerFirstState(Behaviour state, String name) {
        registerState(state, name);
        first = name;
    }

    public void registerLastState(Behaviour state, String name) {
        registerState(state, name);
        lastStates.add(name);
    }

    public void registerState(Behaviour state, String name) {
        if (states.containsKey(name)) {
            throw new IllegalArgumentException("state " + name + " is already registered");
        }
        states.put(name, state);
        names.put(state, name);
        adopt(state);
    }

    /** A transition taken when {@code from} ends with {@code event}. */
    public void registerTransition(String from, String to, int event) {
        registerTransition(from, to, event, new String[0]);
    }

    /** A transition that also resets the named states. */
    public void registerTransition(String from, String to, int event, String[] toBeReset) {
        checkState(from);
        checkState(to);
        transitions.computeIfAbsent(from, k -> new HashMap<>()).put(event, new Transition(to, toBeReset.clone()));
    }

    /** The transition taken when no other matches. */
    public void registerDefaultTransition(String from, String to) {
        registerDefaultTransition(from, to, new String[0]);
    }

    public void registerDefaultTransition(String from, String to, String[] toBeReset) {
        checkState(from);
        checkState(to);
        defaults.put(from, new Transition(to, toBeReset.clone()));
    }

    private void checkState(String name) {
        if (!states.containsKey(name)) {
            throw new IllegalArgumentException("no state named " + name + "; register it first");
        }
    }

    /** The state's behaviour, or {@code null}. */
    public Behaviour getState(String name) {
        return states.get(name);
    }

    /** The name of the current state. */
    public String getCurrentStateName() {
        return currentName;
    }

    /** The exit value of the last state that ended. */
    public int getLastExitValue() {
        return lastExitValue;
    }

    @Override
    public void onStart() {
        if (first == null) {
            throw new IllegalStateException("an FSMBehaviour needs a first state (registerFirstState)");
        }
        currentName = first;
        current = states.get(first);
    }

    @Override
    protected Collection<Behaviour> activeChildren() {
        return current == null ? List.of() : List.of(current);
    }

    @Override
    protected Collection<Behaviour> allChildren() {
        return new ArrayList<>(states.values());
    }

    @Override
    public void action() {
        if (finished || current == null) {
            return;
        }
        if (!stepChild(current)) {
            if (!current.isRunnable()) {
                block();
            }
            return;
        }
        lastExitValue = current.onEnd();
        if (lastStates.contains(currentName)) {
            finished = true;
            return;
        }
        Transition t = transitions.getOrDefault(currentName, Map.of()).get(lastExitValue);
        if (t == null) {
            t = defaults.get(currentName);
        }
        if (t == null) {
            throw new IllegalStateException("FSM state " + currentName + " ended with " + lastExitValue
                    + " and has no transition for it and no default transition");
        }
        for (String r : t.toBeReset()) {
            states.get(r).reset();
        }
        currentName = t.to();
        current = states.get(currentName);
    }

    @Override
    public boolean done() {
        return finished;
    }

    @Override
    public int onEnd() {
        return lastExitValue;
    }

    @Override
    public void reset() {
        super.reset();
        finished = false;
        current = null;
        currentName = null;
    }
}
