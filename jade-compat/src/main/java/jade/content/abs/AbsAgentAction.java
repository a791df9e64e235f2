package jade.content.abs;

import jade.content.AgentAction;

/** An abstract agent action: a concept that can be content, {@code (Sell :book ...)}. */
public class AbsAgentAction extends AbsConcept implements AbsContentElement, AgentAction {
    private static final long serialVersionUID = 1L;
    private boolean contentExpression;

    /** An action of that type. */
    public AbsAgentAction(String typeName) {
        super(typeName);
    }

    /** Sets a slot holding a proposition. */
    public void set(String name, AbsPredicate value) {
        super.set(name, value);
    }

    /** The Java class JADE associates with this kind. */
    public static Class getJavaClass() {
        return AbsAgentAction.class;
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
        return ABS_AGENT_ACTION;
    }
}
