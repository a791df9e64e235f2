package jade.content.abs;

import jade.content.onto.BasicOntology;

import java.util.Arrays;
import java.util.Date;

/** An abstract primitive: a string, integer, float, boolean, date or byte sequence, typed by BasicOntology's names. */
public class AbsPrimitive implements AbsTerm {
    private static final long serialVersionUID = 1L;
    private final String typeName;
    private Object value;

    /** A primitive of that type ({@code BasicOntology.STRING}, ...) without a value yet. */
    public AbsPrimitive(String typeName) {
        this.typeName = typeName;
    }

    private static AbsPrimitive of(String type, Object value) {
        AbsPrimitive p = new AbsPrimitive(type);
        p.value = value;
        return p;
    }

    /** A string. */
    public static AbsPrimitive wrap(String value) {
        return of(BasicOntology.STRING, value);
    }

    /** A boolean. */
    public static AbsPrimitive wrap(boolean value) {
        return of(BasicOntology.BOOLEAN, value);
    }

    /** An integer. */
    public static AbsPrimitive wrap(int value) {
        return of(BasicOntology.INTEGER, value);
    }

    /** An integer. */
    public static AbsPrimitive wrap(long value) {
        return of(BasicOntology.INTEGER, value);
    }

    /** A float. */
    public static AbsPrimitive wrap(float value) {
        return of(BasicOntology.FLOAT, value);
    }

    /** A float. */
    public static AbsPrimitive wrap(double value) {
        return of(BasicOntology.FLOAT, value);
    }

    /** A date. */
    public static AbsPrimitive wrap(Date value) {
        return of(BasicOntology.DATE, value);
    }

    /** A byte sequence. */
    public static AbsPrimitive wrap(byte[] value) {
        return of(BasicOntology.BYTE_SEQUENCE, value);
    }

    /** Sets the value. */
    public void set(String v) {
        value = v;
    }

    /** Sets the value. */
    public void set(boolean v) {
        value = v;
    }

    /** Sets the value. */
    public void set(int v) {
        value = v;
    }

    /** Sets the value. */
    public void set(long v) {
        value = v;
    }

    /** Sets the value. */
    public void set(float v) {
        value = v;
    }

    /** Sets the value. */
    public void set(double v) {
        value = v;
    }

    /** Sets the value. */
    public void set(Date v) {
        value = v;
    }

    /** Sets the value. */
    public void set(byte[] v) {
        value = v;
    }

    /** The value as a string (any value's text). */
    public String getString() {
        return value == null ? null : value.toString();
    }

    /** The value as a boolean. */
    public boolean getBoolean() {
        return (Boolean) value;
    }

    /** The value as an int. */
    public int getInteger() {
        return ((Number) value).intValue();
    }

    /** The value as a long. */
    public long getLong() {
        return ((Number) value).longValue();
    }

    /** The value as a float. */
    public float getFloat() {
        return ((Number) value).floatValue();
    }

    /** The value as a double. */
    public double getDouble() {
        return ((Number) value).doubleValue();
    }

    /** The value as a date. */
    public Date getDate() {
        return (Date) value;
    }

    /** The value as bytes. */
    public byte[] getByteSequence() {
        return (byte[]) value;
    }

    /** The value as it is held. */
    public Object getObject() {
        return value;
    }

    @Override
    public String getTypeName() {
        return typeName;
    }

    /** A primitive has no slot: null. */
    @Override
    public AbsObject getAbsObject(String name) {
        return null;
    }

    /** A primitive has no slot. */
    @Override
    public String[] getNames() {
        return new String[0];
    }

    @Override
    public boolean isGrounded() {
        return value != null;
    }

    /** A primitive has no slot. */
    @Override
    public int getCount() {
        return 0;
    }

    @Override
    public String toString() {
        return value instanceof byte[] b ? Arrays.toString(b) : String.valueOf(value);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AbsPrimitive p && typeName.equals(p.typeName)
                && (value instanceof byte[] a && p.value instanceof byte[] b ? Arrays.equals(a, b) : java.util.Objects.equals(value, p.value));
    }

    @Override
    public int hashCode() {
        return value instanceof byte[] b ? Arrays.hashCode(b) : java.util.Objects.hashCode(value);
    }

    @Override
    public int getAbsType() {
        return ABS_PRIMITIVE;
    }
}
