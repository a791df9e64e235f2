package jade.util.leap;

/** JADE's list interface. */
public interface List extends Collection {
    void add(int index, Object o);

    void clear();

    boolean contains(Object o);

    Object get(int index);

    int indexOf(Object o);

    Object remove(int index);
}
