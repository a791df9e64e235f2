package jade.content.abs;

import java.util.LinkedHashMap;
import java.util.Map;

/** An abstract object with a type name and named slots, kept in the order they were set. */
public class AbsObjectImpl implements AbsObject {
    private static final long serialVersionUID = 1L;
    private final String typeName;
    private final Map<String, AbsObject> slots = new LinkedHashMap<>();

    /** An object of that type. */
    protected AbsObjectImpl(String typeName) {
        this.typeName = typeName;
    }

    @Override
    public String getTypeName() {
        return typeName;
    }

    /** Sets a slot; null removes it. */
    protected void set(String name, AbsObject value) {
        if (value == null) {
            slots.remove(name);
        } else {
            slots.put(name, value);
        }
    }

    @Override
    public AbsObject getAbsObject(String name) {
        return slots.get(name);
    }

    @Override
    public String[] getNames() {
        return slots.keySet().toArray(new String[0]);
    }

    @Override
    public boolean isGrounded() {
        for (AbsObject o : slots.values()) {
            if (!o.isGrounded()) {
                return false;
            }
        }
        return true;
    }

    @Override
    public int getCount() {
        return slots.size();
    }

    @Override
    public String toString() {
        StringBuilder b = new StringBuilder("(").append(typeName);
        for (Map.Entry<String, AbsObject> e : slots.entrySet()) {
            b.append(" :").append(e.getKey()).append(' ').append(e.getValue());
        }
        return b.append(')').toString();
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AbsObjectImpl other && other.getClass() == getClass() && typeName.equals(other.typeName)
                && slots.equals(other.slots);
    }

    @Override
    public int hashCode() {
        return typeName.hashCode() * 31 + slots.hashCode();
    }

    @Override
    public int getAbsType() {
        return UNKNOWN;
    }
}
