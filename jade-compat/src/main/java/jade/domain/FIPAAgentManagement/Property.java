package jade.domain.FIPAAgentManagement;

import java.util.Objects;

/** A name and a value, in a service description. */
public class Property implements jade.content.Concept {
    private static final long serialVersionUID = 1L;
    private String name;
    private Object value;

    public Property() {
    }

    public Property(String name, Object value) {
        this.name = name;
        this.value = value;
    }

    public void setName(String n) {
        name = n;
    }

    public String getName() {
        return name;
    }

    public void setValue(Object v) {
        value = v;
    }

    public Object getValue() {
        return value;
    }

    /** Properties as Java properties (values as text). */
    public static java.util.Properties convertPropertyListToProperties(java.util.List<Property> l) {
        java.util.Properties p = new java.util.Properties();
        for (Property x : l) {
            p.setProperty(x.getName(), String.valueOf(x.getValue()));
        }
        return p;
    }

    /** Same name, and the same value if this one has a value. */
    public boolean match(Property p) {
        return Objects.equals(name, p.name) && (value == null || Objects.equals(String.valueOf(value), String.valueOf(p.value)));
    }

    @Override
    public Object clone() {
        return new Property(name, value);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Property p && Objects.equals(name, p.name) && Objects.equals(value, p.value);
    }

    @Override
    public int hashCode() {
        return Objects.hash(name, value);
    }
}
