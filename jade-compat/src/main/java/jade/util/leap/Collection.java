package jade.util.leap;

/** JADE's small collection interface (raw objects, as in JADE's LEAP profile). */
public interface Collection {
    /** Adds an element; true if the collection changed. */
    boolean add(Object o);

    boolean isEmpty();

    /** Removes one occurrence; true if it was there. */
    boolean remove(Object o);

    Iterator iterator();

    Object[] toArray();

    int size();
}
