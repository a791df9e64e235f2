package jade.util.leap;

/** JADE's {@code HashSet}, kept in a {@link java.util.LinkedHashSet} (insertion order, so runs repeat). */
public class HashSet implements Set, Cloneable, Serializable {
    private static final long serialVersionUID = 1L;
    private final java.util.LinkedHashSet<Object> items;

    public HashSet() {
        items = new java.util.LinkedHashSet<>();
    }

    public HashSet(Collection c) {
        this();
        addAll(c);
    }

    public HashSet(int capacity) {
        items = new java.util.LinkedHashSet<>(capacity);
    }

    @Override
    public boolean add(Object o) {
        return items.add(o);
    }

    @Override
    public boolean isEmpty() {
        return items.isEmpty();
    }

    @Override
    public Iterator iterator() {
        return Iterators.of(items.iterator());
    }

    @Override
    public boolean remove(Object o) {
        return items.remove(o);
    }

    @Override
    public int size() {
        return items.size();
    }

    @Override
    public Object[] toArray() {
        return items.toArray();
    }

    public Object[] toArray(Object[] a) {
        return items.toArray(a);
    }

    public void clear() {
        items.clear();
    }

    public boolean contains(Object o) {
        return items.contains(o);
    }

    @Override
    public Object clone() {
        HashSet s = new HashSet();
        s.items.addAll(items);
        return s;
    }

    @Override
    public int hashCode() {
        return items.hashCode();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof HashSet h && items.equals(h.items);
    }

    public boolean addAll(Collection c) {
        boolean changed = false;
        for (Object o : c.toArray()) {
            changed |= items.add(o);
        }
        return changed;
    }

    public boolean containsAll(Collection c) {
        for (Object o : c.toArray()) {
            if (!items.contains(o)) {
                return false;
            }
        }
        return true;
    }

    public boolean removeAll(Collection c) {
        boolean changed = false;
        for (Object o : c.toArray()) {
            changed |= items.remove(o);
        }
        return changed;
    }

    @Override
    public String toString() {
        return items.toString();
    }
}
