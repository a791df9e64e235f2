package jade.content.abs;

import jade.content.Predicate;

/** An abstract predicate (or an SL operator): its arguments are slots in schema order. */
public class AbsPredicate extends AbsPrimitiveSlotsHolder implements AbsContentElement, Predicate {
    private static final long serialVersionUID = 1L;
    private boolean contentExpression;
    private boolean metaFormula;

    /** A predicate of that type. */
    public AbsPredicate(String typeName) {
        super(typeName);
    }

    @Override
    public void set(String name, AbsObject value) {
        super.set(name, value);
    }

    /** A term slot's value, or null. */
    public AbsTerm getAbsTerm(String name) {
        return (AbsTerm) getAbsObject(name);
    }

    /** The Java class JADE associates with this kind. */
    public static Class getJavaClass() {
        return AbsPredicate.class;
    }

    @Override
    public boolean isAContentExpression() {
        return contentExpression;
    }

    @Override
    public void setIsAContentExpression(boolean flag) {
        this.contentExpression = flag;
    }

    /** Whether it stands for a formula variable (JADE's meta formulas; recorded only). */
    public final boolean isMetaFormula() {
        return metaFormula;
    }

    /** Marks it a meta formula (recorded only). */
    public final void setIsMetaFormula(boolean flag) {
        this.metaFormula = flag;
    }

    @Override
    public int getAbsType() {
        return ABS_PREDICATE;
    }
}
