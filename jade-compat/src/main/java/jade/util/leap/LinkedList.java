package jade.util.leap;

/** JADE's {@code LinkedList}, kept in a {@link java.util.LinkedList}. */
public class LinkedList implements List, Serializable {
    private static final long serialVersionUID = 1L;
    final java.util.LinkedList<Object> items;

    public LinkedList() {
        items = new java.util.LinkedList<>();
    }

    public Object removeFirst() {
        return items.removeFirst();
    }

    public void addFirst(Object o) {
        items.addFirst(o);
    }

    public void addLast(Object o) {
        items.addLast(o);
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
        return o instanceof LinkedList other && items.equals(other.items);
    }

    @Override
    public int hashCode() {
        return items.hashCode();
    }
}
