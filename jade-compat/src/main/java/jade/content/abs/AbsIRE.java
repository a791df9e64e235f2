package jade.content.abs;

/**
 * An abstract referential expression, {@code (iota ?x (Owns ?x ...))}, {@code any} or {@code all}:
 * a variable (or a term of variables) and a proposition about it.
 */
public class AbsIRE extends AbsObjectImpl implements AbsContentElement, AbsTerm {
    private static final long serialVersionUID = 1L;
    private static final String TERM = "variable";
    private static final String PROPOSITION = "proposition";
    private boolean contentExpression;

    /** An expression of that kind: {@code iota}, {@code any} or {@code all}. */
    public AbsIRE(String typeName) {
        super(typeName);
    }

    /** Sets the variable. */
    public void setVariable(AbsVariable variable) {
        set(TERM, variable);
    }

    /** Sets several variables, as a sequence. */
    public void setVariables(AbsAggregate variables) {
        set(TERM, variables);
    }

    /** Sets the term the expression refers through. */
    public void setTerm(AbsTerm term) {
        set(TERM, term);
    }

    /** Sets the proposition. */
    public void setProposition(AbsPredicate proposition) {
        set(PROPOSITION, proposition);
    }

    /** The variable, or null when the term is not one variable. */
    public AbsVariable getVariable() {
        return getAbsObject(TERM) instanceof AbsVariable v ? v : null;
    }

    /** The variables, or null when the term is not an aggregate. */
    public AbsAggregate getVariables() {
        return getAbsObject(TERM) instanceof AbsAggregate a ? a : null;
    }

    /** The term. */
    public AbsTerm getTerm() {
        return (AbsTerm) getAbsObject(TERM);
    }

    /** The proposition. */
    public AbsPredicate getProposition() {
        return (AbsPredicate) getAbsObject(PROPOSITION);
    }

    /** The Java class JADE associates with this kind. */
    public static Class getJavaClass() {
        return AbsIRE.class;
    }

    @Override
    public boolean isAContentExpression() {
        return contentExpression;
    }

    @Override
    public void setIsAContentExpression(boolean flag) {
        this.contentExpression = flag;
    }

    @Override
    public int getAbsType() {
        return ABS_IRE;
    }
}
