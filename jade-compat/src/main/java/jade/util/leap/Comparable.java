package jade.util.leap;

/** JADE's raw {@link java.lang.Comparable}, as JADE's {@code AID} implements it. */
@SuppressWarnings("rawtypes")
public interface Comparable extends java.lang.Comparable {
}
