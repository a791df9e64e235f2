package jade.util.leap;

/** JADE's {@code HashMap}, kept in a {@link java.util.HashMap}. */
public class HashMap implements Map, Serializable {
    private static final long serialVersionUID = 1L;
    private final java.util.HashMap<Object, Object> items;

    public HashMap() {
        items = new java.util.HashMap<>();
    }

    public HashMap(int capacity) {
        items = new java.util.HashMap<>(capacity);
    }

    public HashMap(int capacity, float loadFactor) {
        items = new java.util.HashMap<>(capacity, loadFactor);
    }

    @Override
    public boolean isEmpty() {
        return items.isEmpty();
    }

    @Override
    public Object remove(Object key) {
        return items.remove(key);
    }

    @Override
    public Object put(Object key, Object value) {
        return items.put(key, value);
    }

    @Override
    public Object get(Object key) {
        return items.get(key);
    }

    @Override
    public int size() {
        return items.size();
    }

    @Override
    public boolean containsKey(Object key) {
        return items.containsKey(key);
    }

    @Override
    public void clear() {
        items.clear();
    }

    @Override
    public String toString() {
        return items.toString();
    }

    @Override
    public Set keySet() {
        HashSet s = new HashSet();
        for (Object k : items.keySet()) {
            s.add(k);
        }
        return s;
    }

    @Override
    public Collection values() {
        ArrayList l = new ArrayList();
        for (Object v : items.values()) {
            l.add(v);
        }
        return l;
    }
}
