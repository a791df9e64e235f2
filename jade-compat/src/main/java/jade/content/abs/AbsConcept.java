package jade.content.abs;

import jade.content.Concept;

/** An abstract concept: a type name and named term slots, {@code (Book :title X)}. */
public class AbsConcept extends AbsPrimitiveSlotsHolder implements AbsTerm, Concept {
    private static final long serialVersionUID = 1L;

    /** A concept of that type. */
    public AbsConcept(String typeName) {
        super(typeName);
    }

    /** Sets a term slot. */
    public void set(String name, AbsTerm value) {
        super.set(name, value);
    }

    /** A term slot's value, or null. */
    public AbsTerm getAbsTerm(String name) {
        return (AbsTerm) getAbsObject(name);
    }

    /** The Java class JADE associates with this kind. */
    public static Class getJavaClass() {
        return AbsConcept.class;
    }

    @Override
    public int getAbsType() {
        return ABS_CONCEPT;
    }
}
