package jade.content.abs;

import java.util.Date;

/** An abstract object whose slots can be set and read as Java primitives. */
public class AbsPrimitiveSlotsHolder extends AbsObjectImpl {
    private static final long serialVersionUID = 1L;

    /** An object of that type. */
    protected AbsPrimitiveSlotsHolder(String typeName) {
        super(typeName);
    }

    @Override
    public void set(String name, AbsObject value) {
        super.set(name, value);
    }

    /** Sets a string slot. */
    public void set(String name, String value) {
        set(name, value == null ? null : AbsPrimitive.wrap(value));
    }

    /** Sets a boolean slot. */
    public void set(String name, boolean value) {
        set(name, AbsPrimitive.wrap(value));
    }

    /** Sets an integer slot. */
    public void set(String name, int value) {
        set(name, AbsPrimitive.wrap(value));
    }

    /** Sets an integer slot. */
    public void set(String name, long value) {
        set(name, AbsPrimitive.wrap(value));
    }

    /** Sets a float slot. */
    public void set(String name, float value) {
        set(name, AbsPrimitive.wrap(value));
    }

    /** Sets a float slot. */
    public void set(String name, double value) {
        set(name, AbsPrimitive.wrap(value));
    }

    /** Sets a date slot. */
    public void set(String name, Date value) {
        set(name, value == null ? null : AbsPrimitive.wrap(value));
    }

    /** Sets a byte-sequence slot. */
    public void set(String name, byte[] value) {
        set(name, value == null ? null : AbsPrimitive.wrap(value));
    }

    private AbsPrimitive primitive(String name) {
        AbsObject o = getAbsObject(name);
        if (o == null) {
            throw new NullPointerException("no slot " + name + " in " + getTypeName());
        }
        if (!(o instanceof AbsPrimitive p)) {
            throw new ClassCastException("slot " + name + " of " + getTypeName() + " is not a primitive");
        }
        return p;
    }

    /** A string slot's value, or null when absent. */
    public String getString(String name) {
        return getAbsObject(name) == null ? null : primitive(name).getString();
    }

    /** A boolean slot's value. */
    public boolean getBoolean(String name) {
        return primitive(name).getBoolean();
    }

    /** An integer slot's value. */
    public int getInteger(String name) {
        return primitive(name).getInteger();
    }

    /** An integer slot's value. */
    public long getLong(String name) {
        return primitive(name).getLong();
    }

    /** A float slot's value. */
    public float getFloat(String name) {
        return primitive(name).getFloat();
    }

    /** A float slot's value. */
    public double getDouble(String name) {
        return primitive(name).getDouble();
    }

    /** A date slot's value, or null when absent. */
    public Date getDate(String name) {
        return getAbsObject(name) == null ? null : primitive(name).getDate();
    }

    /** A byte-sequence slot's value, or null when absent. */
    public byte[] getByteSequence(String name) {
        return getAbsObject(name) == null ? null : primitive(name).getByteSequence();
    }
}
