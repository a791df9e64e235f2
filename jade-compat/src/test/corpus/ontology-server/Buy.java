import jade.content.AgentAction;

/** An action the shop has no serve method for. */
public class Buy implements AgentAction {
    private String item;

    public String getItem() {
        return item;
    }

    public void setItem(String item) {
        this.item = item;
    }
}
