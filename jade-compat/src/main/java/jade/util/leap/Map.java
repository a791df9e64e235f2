package jade.util.leap;

/** JADE's map interface. */
public interface Map {
    boolean isEmpty();

    Object remove(Object key);

    Set keySet();

    Collection values();

    Object put(Object key, Object value);

    boolean containsKey(Object key);

    Object get(Object key);

    int size();

    void clear();
}
