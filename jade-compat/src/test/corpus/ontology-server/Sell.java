import jade.content.AgentAction;

/** An action the shop serves (serveSellRequest). */
public class Sell implements AgentAction {
    private String item;

    public String getItem() {
        return item;
    }

    public void setItem(String item) {
        this.item = item;
    }
}
