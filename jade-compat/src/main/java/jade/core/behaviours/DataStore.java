package jade.core.behaviours;

/** A map behaviours share to pass data (JADE's DataStore), e.g. between the states of an FSM. */
public class DataStore extends jade.util.leap.HashMap {
    private static final long serialVersionUID = 1L;

    public DataStore() {
    }

    public DataStore(int size) {
        super(size);
    }
}
