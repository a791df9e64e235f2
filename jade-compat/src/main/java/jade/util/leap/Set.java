package jade.util.leap;

/** JADE's set interface. */
public interface Set extends Collection {
}
