package jade.core;

/** An agent's life-cycle state as an object: a value ({@code Agent.AP_ACTIVE}, ...) and its name. */
public class AgentState implements Comparable<Object> {
    private static final String[] NAMES = {"Illegal MIN state", "Initiated", "Active", "Idle", "Suspended", "Waiting",
        "Deleted", "Transit", "Copy", "Gone", "Saving", "Loading", "Frozen", "Illegal MAX state"};
    private static final AgentState[] ALL = new AgentState[NAMES.length];

    static {
        for (int i = 0; i < NAMES.length; i++) {
            ALL[i] = new AgentState();
            ALL[i].setName(NAMES[i]);
            ALL[i].setValue(i);
        }
    }

    private String name;
    private int value;

    public AgentState() {
    }

    /** The state of this value ({@code Agent.AP_MIN}..{@code Agent.AP_MAX}). */
    public static AgentState getInstance(int value) {
        if (value < 0 || value >= ALL.length) {
            throw new IllegalArgumentException("no agent state " + value);
        }
        return ALL[value];
    }

    public static AgentState[] getAllInstances() {
        return ALL.clone();
    }

    public void setName(String n) {
        name = n;
    }

    public String getName() {
        return name;
    }

    public void setValue(int v) {
        value = v;
    }

    public int getValue() {
        return value;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AgentState && ((AgentState) o).value == value
                || o instanceof String && ((String) o).equalsIgnoreCase(name);
    }

    @Override
    public int hashCode() {
        return value;
    }

    @Override
    public String toString() {
        return name;
    }

    @Override
    public int compareTo(Object o) {
        return Integer.compare(value, ((AgentState) o).value);
    }
}
