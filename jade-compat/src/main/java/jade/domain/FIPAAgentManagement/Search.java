package jade.domain.FIPAAgentManagement;

import jade.content.AgentAction;

/** FIPA's {@code search} action: a description to match and the search's constraints. */
public class Search implements AgentAction {
    private static final long serialVersionUID = 1L;
    private Object description;
    private SearchConstraints constraints;

    /** An empty action. */
    public Search() {
    }

    /** Sets the description to match. */
    public void setDescription(Object description) {
        this.description = description;
    }

    /** The description to match. */
    public Object getDescription() {
        return description;
    }

    /** Sets the constraints. */
    public void setConstraints(SearchConstraints constraints) {
        this.constraints = constraints;
    }

    /** The constraints. */
    public SearchConstraints getConstraints() {
        return constraints;
    }
}
