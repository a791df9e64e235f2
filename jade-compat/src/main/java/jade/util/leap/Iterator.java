package jade.util.leap;

/** JADE's iterator: a raw {@link java.util.Iterator}. */
@SuppressWarnings("rawtypes")
public interface Iterator extends java.util.Iterator {
}
