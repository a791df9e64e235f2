package jade.wrapper;

/** The state of an agent or container, by code and name. */
public class State implements jade.util.leap.Serializable {
    private static final long serialVersionUID = 1L;
    private final int code;
    private final String name;

    public State(int code, String name) {
        this.code = code;
        this.name = name;
    }

    public int getCode() {
        return code;
    }

    public String getName() {
        return name;
    }

    @Override
    public String toString() {
        return name;
    }
}
