package jade.util.leap;

/** JADE's marker for serialisable types: {@link java.io.Serializable} under JADE's name. */
public interface Serializable extends java.io.Serializable {
}
