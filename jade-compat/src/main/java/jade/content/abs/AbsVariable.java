package jade.content.abs;

/** An abstract variable, {@code ?x}, with the type it stands for. */
public class AbsVariable extends AbsObjectImpl implements AbsTerm {
    private static final long serialVersionUID = 1L;
    private String name;
    private String type;
    private boolean metaTerm;

    /** A variable without a name yet. */
    public AbsVariable() {
        super("variable");
    }

    /** The variable {@code ?name} of that type (a schema name, or null). */
    public AbsVariable(String name, String type) {
        this();
        this.name = name;
        this.type = type;
    }

    /** Sets its name. */
    public void setName(String name) {
        this.name = name;
    }

    /** Sets its type. */
    public void setType(String type) {
        this.type = type;
    }

    /** Its name, without the question mark. */
    public String getName() {
        return name;
    }

    /** Its type, or null. */
    public String getType() {
        return type;
    }

    /** A variable is not grounded. */
    @Override
    public boolean isGrounded() {
        return false;
    }

    /** The Java class JADE associates with this kind. */
    public static Class getJavaClass() {
        return AbsVariable.class;
    }

    /** Whether it stands for a term variable (recorded only). */
    public final boolean isMetaTerm() {
        return metaTerm;
    }

    /** Marks it a meta term (recorded only). */
    public final void setIsMetaTerm(boolean flag) {
        this.metaTerm = flag;
    }

    @Override
    public String toString() {
        return "?" + name;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof AbsVariable v && java.util.Objects.equals(name, v.name);
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hashCode(name);
    }

    @Override
    public int getAbsType() {
        return ABS_VARIABLE;
    }
}
