package jade.util.leap;

/** JADE's {@code ArrayList}, kept in a {@link java.util.ArrayList}. */
public class ArrayList implements List, Serializable {
    private static final long serialVersionUID = 1L;
    final java.util.ArrayList<Object> items;

    public ArrayList() {
        items = new java.util.ArrayList<>();
    }

    public ArrayList(int capacity) {
        items = new java.util.ArrayList<>(capacity);
    }

    /** A JADE list holding the elements of a Java list. */
    public ArrayList(java.util.ArrayList<?> l) {
        items = new java.util.ArrayList<>(l);
    }

    /** The elements as a Java list (a copy). */
    public java.util.List<Object> toList() {
        return new java.util.ArrayList<>(items);
    }

    /** Replaces the elements with those of a Java list. */
    public void fromList(java.util.List<?> l) {
        items.clear();
        items.addAll(l);
    }

    @Override
    public Object clone() {
        return new ArrayList(items);
    }

    @Override
    public void clear() {
        items.clear();
    }

    @Override
    public boolean contains(Object o) {
        return items.contains(o);
    }

    @Override
    public Object get(int index) {
        return items.get(index);
    }

    @Override
    public int indexOf(Object o) {
        return items.indexOf(o);
    }

    @Override
    public Object remove(int index) {
        return items.remove(index);
    }

    @Override
    public void add(int index, Object o) {
        items.add(index, o);
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
    public boolean remove(Object o) {
        return items.remove(o);
    }

    @Override
    public String toString() {
        return items.toString();
    }

    @Override
    public Iterator iterator() {
        return Iterators.of(items.iterator());
    }

    @Override
    public Object[] toArray() {
        return items.toArray();
    }

    @Override
    public int size() {
        return items.size();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ArrayList other && items.equals(other.items);
    }

    @Override
    public int hashCode() {
        return items.hashCode();
    }
}
